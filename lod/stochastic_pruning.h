// Stochastic pruning (Cook, Halstead, Planck and Ryu 2007): the leaves get one random priority
// order, fixed per model; a level of detail draws the first lambda fraction of that order and
// scales each survivor's area by s (Cook: s = 1 / lambda, so the total leaf area stays the same).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lod/pruned_mesh.h"

namespace voltree {

// A random permutation of 0..count-1 from `seed` (same seed, same order, on every platform).
std::vector<uint32_t> RandomLeafOrder(size_t count, uint64_t seed);

// How many leaves a fraction `lambda` in (0, 1] keeps: lambda * count rounded, at least one when
// there are any. Throws Error for lambda outside (0, 1].
size_t KeptLeafCount(size_t count, double lambda);

// The first KeptLeafCount(order.size(), lambda) leaves of `order`, each with `area_scale`.
std::vector<LeafDraw> PruneLeaves(const std::vector<uint32_t>& order, double lambda, double area_scale);

// Cook's area-preserving scale, 1 / lambda.
double CookAreaScale(double lambda);

}  // namespace voltree
