// A tiny deterministic random source for procedural trees. The standard distributions are
// implementation-defined, so trees would differ between standard libraries; SplitMix64 and the
// hand-written conversions below give the same numbers everywhere.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace voltree {

// Mixes a 64-bit value (SplitMix64 finalizer); also used to hash lattice points for noise.
constexpr uint64_t MixBits(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr uint64_t HashCombine(uint64_t a, uint64_t b) { return MixBits(a * 0x9E3779B97F4A7C15ull + b); }

class TreeRandom {
 public:
  explicit TreeRandom(uint64_t seed) : state_(MixBits(seed ^ 0x5DEECE66Dull)) {}

  uint64_t Next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return MixBits(state_);
  }
  // Uniform in [0, 1) with 24 bits, exactly representable as float.
  float Uniform() { return static_cast<float>(Next() >> 40) * 0x1.0p-24f; }
  float Uniform(float lo, float hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform in [-amount, amount].
  float Jitter(float amount) { return amount * (2.0f * Uniform() - 1.0f); }
  int Index(int count) { return static_cast<int>((Next() >> 33) % static_cast<uint64_t>(count)); }
  // Rounds x up or down at random so that the expected value is x.
  int RoundStochastic(float x) {
    const float whole = static_cast<float>(static_cast<int>(x));
    return static_cast<int>(whole) + (Uniform() < x - whole ? 1 : 0);
  }
  // A direction uniformly distributed on the unit sphere (rejection sampling, no trig).
  Eigen::Vector3f UnitVector() {
    for (;;) {
      const Eigen::Vector3f v(Jitter(1.0f), Jitter(1.0f), Jitter(1.0f));
      const float n2 = v.squaredNorm();
      if (n2 > 1e-4f && n2 <= 1.0f) return v / std::sqrt(n2);
    }
  }
  // An independent stream for a sub-task, so that its consumption does not shift the parent's.
  TreeRandom Fork(uint64_t salt) { return TreeRandom(HashCombine(Next(), salt)); }

 private:
  uint64_t state_;
};

}  // namespace voltree
