// Greedy k-means++ seeding (Arthur & Vassilvitskii 2007), the start of GLA: each centre is the
// best of `trials` candidates drawn with probability proportional to the squared distance to the
// nearest centre so far (OpenCV's KMEANS_PP_CENTERS does the same with 3 trials).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "compress/training_set.h"

namespace voltree {

struct Seeds {
  Codebook centres;
  // Every vector's nearest centre (lowest index on ties) and squared distance to it: exactly what
  // AssignNearest(centres) returns, found along the way.
  std::vector<uint32_t> nearest;
  std::vector<float> distances;
};

// `count` centres (at most the number of vectors), deterministic for a given seed whatever the
// number of threads. All trials of a step are measured in one parallel pass, and two bounds skip
// most vectors without measuring them (compress/center_bounds.h). The bounds need one metric for
// all vectors, so a weighted set is seeded on plain L2 distances (its weights are texel alphas,
// and its transparent texels already hold their billboard's mean colour); `nearest` and
// `distances` are still the weighted ones. `use_simd` = false keeps the bounds to the baseline
// instruction set (tests compare the two).
Seeds SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials = 3, bool use_simd = true);

}  // namespace voltree
