#include "lod/stochastic_pruning.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace voltree {
namespace {

// splitmix64: a small, fully specified generator, so orders match across standard libraries
// (std::shuffle's use of its engine is implementation-defined).
uint64_t NextRandom(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

std::vector<uint32_t> RandomLeafOrder(size_t count, uint64_t seed) {
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  uint64_t state = seed;
  // Fisher-Yates; the modulo bias (< count / 2^64) does not matter here.
  for (size_t i = count; i > 1; --i) std::swap(order[i - 1], order[NextRandom(state) % i]);
  return order;
}

size_t KeptLeafCount(size_t count, double lambda) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: the kept fraction lambda = ", lambda, " is outside (0, 1]");
  if (count == 0) return 0;
  return std::clamp<size_t>(static_cast<size_t>(std::llround(lambda * static_cast<double>(count))), 1, count);
}

std::vector<LeafDraw> PruneLeaves(const std::vector<uint32_t>& order, double lambda, double area_scale) {
  const size_t kept = KeptLeafCount(order.size(), lambda);
  std::vector<LeafDraw> draws;
  draws.reserve(kept);
  for (size_t i = 0; i < kept; ++i) draws.push_back({order[i], area_scale});
  return draws;
}

double CookAreaScale(double lambda) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: the kept fraction lambda = ", lambda, " is outside (0, 1]");
  return 1 / lambda;
}

}  // namespace voltree
