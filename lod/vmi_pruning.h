// Viewpoint-driven leaf pruning (foliage simplification by viewpoint mutual information, VMI):
// the leaf removed next is the one whose removal changes the viewpoint mutual information
// I(v; F) = sum_o p(o|v) log(p(o|v) / p(o)) least,
// summed over the views (their eqs. 1 and 4), with p(o|v) the leaf's share of the visible leaf
// pixels in view v and p(o) its mean over the views. The removed leaf's size goes to its nearest
// remaining leaf in proportion to that cost (their eq. 5): Size(l') += Size(l) * Lpru(l).
//
// Where we depart, for trees of tens of thousands of leaves (the paper's greedy loop re-renders
// every candidate, O(P V L^2)): the cost of removing a leaf is computed from one id render per
// view with p(o) held fixed (the leaf's pixels simply leave the histogram, disocclusion ignored),
// which is exact up to those two effects and O(V L); the ranking is redone with fresh renders after
// every `round_fraction` of the remaining leaves is removed. Lpru is divided by the round's
// largest cost to put it in [0, 1], which the paper assumes without saying how.
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "lod/leaf_id_renderer.h"
#include "lod/pruned_mesh.h"

namespace voltree {

struct VmiRemoval {
  uint32_t leaf = 0;
  double cost = 0;  // Lpru in [0, 1]
};

// The VMI of each view from per-leaf visible pixel counts (`pixels[v][leaf]`), and the cost of
// removing each leaf (sum over views of the change); exposed for tests.
std::vector<double> ViewpointMutualInformation(const std::vector<std::vector<uint32_t>>& pixels);
std::vector<double> LeafRemovalCosts(const std::vector<std::vector<uint32_t>>& pixels);

// Removes leaves, cheapest first, until `keep` remain; `views` are where the ids are rendered.
std::vector<VmiRemoval> VmiRemovalSequence(LeafIdRenderer& ids, size_t leaf_count, const std::vector<View>& views,
                                           size_t keep, double round_fraction = 0.3);

// The leaves left after the first `removals` of `sequence`, each grown by eq. 5 (sizes are areas)
// with the nearest remaining leaf by centre distance.
std::vector<LeafDraw> VmiLeafDraws(const std::vector<Leaf>& leaves, const std::vector<VmiRemoval>& sequence,
                                   size_t removals);

}  // namespace voltree
