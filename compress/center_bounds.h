// Bounds that rule out, without measuring them, the vectors a new k-means++ centre cannot take
// from their current centre. x, whose nearest centre is a, moves to a candidate c only if
// |x - c| < |x - a|, that is (x - a).(c - a) > |c - a|^2 / 2. Two bounds on that dot product:
//  - the triangle inequality: it is at most |x - a| |c - a|, so x with 4 |x - a|^2 < |c - a|^2
//    stay; with a cell's vectors sorted by |x - a|, those that may move are a suffix;
//  - the sketch: on the principal axes P, and the rest R, it is P(x - a).P(c - a) plus at most
//    |R(x - a)| |R(c - a)|; texture vectors keep little outside a dozen axes, so this rules out
//    most of that suffix for 16 multiply-adds instead of 48.
// Only vectors that pass both are measured, and the measure decides (kmeans_plus_plus.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voltree {

constexpr int kSketchAxes = 14;  // principal axes in a sketch: with two more terms, 16 floats (64 bytes)

// A sketch of x - a and a probe of c - a are laid out so that the bound is one 16-term dot product:
//   x: P(x - a) (kSketchAxes), |R(x - a)| rounded up, |x - a|
//   c: P(c - a) (kSketchAxes), |R(c - a)| rounded up, 0.1 % of |c - a| (a margin for rounding)
struct alignas(64) Sketch {
  float terms[16];
};

// The sketch of x - a (probe = false) or the probe of c - a (probe = true), from P(x) and P(a)
// (`axes` <= kSketchAxes floats each) and the exact |x - a|^2.
Sketch MakeSketch(const float* projected_x, const float* projected_a, int axes, float norm2, bool probe);

// A member of chunk `chunk` that passed the bounds for some trials (bit t set: trial t).
struct Passed {
  uint32_t chunk, member;
  uint64_t trials;
};

// One run of a cell for a measurement: members [begin, end) of an arena (their nearest squared
// distance, 0 for one that moved on, and their sketches); trial t may take those from first[t]
// on (the triangle bound). Probes and squared gaps |c - a|^2 come in groups of four trials
// (unused slots: a gap of +infinity).
struct Run {
  uint32_t chunk;
  size_t begin, end;
  const float* nearest;
  const Sketch* sketches;
  const size_t* first;
  size_t trials;
  const Sketch* probes;
  const float* gaps2;
};

// Appends to `passed` the members of `run` that the bounds cannot rule out for some trial, with
// AVX2 when `avx2` (and the CPU has it; see core/cpu_features.h).
void CollectPassed(const Run& run, bool avx2, std::vector<Passed>& passed);

}  // namespace voltree
