#include "lod/vmi_pruning.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "lod/leaf_separation.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

// Two leaves, each seen by one view only: p(o) = 1/2 each, and each view's VMI is
// 1 * log(1 / (1/2)) = log 2. Removing a leaf empties its view (VMI 0): cost log 2.
TEST(VmiPruning, MutualInformationAndRemovalCostsByHand) {
  const std::vector<std::vector<uint32_t>> pixels = {{10, 0, 0}, {0, 10, 0}};
  const std::vector<double> vmi = ViewpointMutualInformation(pixels);
  ASSERT_EQ(vmi.size(), 2u);
  EXPECT_NEAR(vmi[0], std::log(2.0), 1e-12);
  EXPECT_NEAR(vmi[1], std::log(2.0), 1e-12);
  const std::vector<double> costs = LeafRemovalCosts(pixels);
  EXPECT_NEAR(costs[0], std::log(2.0), 1e-12);
  EXPECT_NEAR(costs[1], std::log(2.0), 1e-12);
  EXPECT_EQ(costs[2], 0.0);  // never seen: free to remove
  // Every leaf seen equally from every view: no information, nothing to lose.
  EXPECT_NEAR(ViewpointMutualInformation({{5, 5}, {5, 5}})[0], 0.0, 1e-12);
}

TEST(VmiPruning, ARemovedLeafGrowsItsNearestNeighbourByItsCost) {
  const TreeMesh mesh = test::SyntheticFoliage(3, 0.1f);
  std::vector<Leaf> leaves = SeparateLeaves(mesh);
  leaves[0].centre = {0, 0, 0}, leaves[1].centre = {1, 0, 0}, leaves[2].centre = {5, 0, 0};
  const std::vector<VmiRemoval> sequence = {{0, 0.5}, {1, 1.0}};
  std::vector<LeafDraw> draws = VmiLeafDraws(leaves, sequence, 1);
  ASSERT_EQ(draws.size(), 2u);
  EXPECT_EQ(draws[0].leaf, 1u);
  EXPECT_NEAR(draws[0].area_scale, 1.5, 1e-5);  // its own area plus half of leaf 0's
  EXPECT_NEAR(draws[1].area_scale, 1.0, 1e-5);
  // Removing leaf 1 too hands all its (grown) size to leaf 2.
  draws = VmiLeafDraws(leaves, sequence, 2);
  ASSERT_EQ(draws.size(), 1u);
  EXPECT_EQ(draws[0].leaf, 2u);
  EXPECT_NEAR(draws[0].area_scale, 2.5, 1e-5);
  EXPECT_THROW(VmiLeafDraws(leaves, sequence, 3), Error);
}

}  // namespace
}  // namespace voltree
