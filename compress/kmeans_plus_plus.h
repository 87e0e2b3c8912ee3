// Greedy k-means++ seeding (Arthur & Vassilvitskii 2007), the start of GLA: each centre is the
// best of `trials` candidates drawn with probability proportional to the squared distance to the
// nearest centre so far (OpenCV's KMEANS_PP_CENTERS does the same with 3 trials).
#pragma once

#include <cstddef>
#include <cstdint>

#include "compress/training_set.h"

namespace voltree {

// `count` centres (at most the number of vectors), deterministic for a given seed whatever the
// number of threads. Each candidate is one parallel pass over the vectors; for plain L2,
// |c - a| >= 2 |x - a| (a = x's centre) proves c is not nearer to x without measuring it.
Codebook SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials = 3);

}  // namespace voltree
