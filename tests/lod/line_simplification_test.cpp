#include "lod/line_simplification.h"

#include <gtest/gtest.h>

#include "lod/branch_skeleton.h"
#include "lod/synthetic_branches.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

TEST(BranchSkeleton, TheTubesBecomeOneConnectedTreeAsWideAsTheBranches) {
  const BranchSkeleton skeleton = ExtractBranchSkeleton(test::SyntheticBranches());
  ASSERT_TRUE(IsConnectedTree(skeleton));
  EXPECT_GT(skeleton.SegmentCount(), 20u);
  // The trunk's nodes lie on its axis and its segments are about its diameter wide.
  int on_trunk = 0;
  for (const SkeletonNode& node : skeleton.nodes) {
    if (node.parent < 0 || node.position.head<2>().norm() > 0.01f || node.position.z() > 0.55f) continue;
    ++on_trunk;
    EXPECT_NEAR(node.width, 0.1f, 0.03f);  // a band holds up to two rings: a little wider
  }
  EXPECT_GT(on_trunk, 3);
  EXPECT_EQ(SkeletonLines(skeleton).size(), skeleton.SegmentCount());
}

TEST(BranchSkeleton, AMeshWithoutBarkHasNone) {
  TreeMesh mesh = test::SyntheticFoliage(10, 0.1f);
  mesh.groups.erase(mesh.groups.begin());
  EXPECT_TRUE(ExtractBranchSkeleton(mesh).nodes.empty());
}

TEST(LineSimplification, EveryLevelKeepsTheBranchGraphConnectedDownToOneLine) {
  const BranchSkeleton skeleton = ExtractBranchSkeleton(test::SyntheticBranches());
  const LineHierarchy hierarchy = SimplifyLines(skeleton);
  ASSERT_EQ(hierarchy.merges.size(), skeleton.SegmentCount() - 1);
  for (size_t m = 0; m <= hierarchy.merges.size(); ++m) {
    const BranchSkeleton level = LinesAfter(hierarchy, m);
    ASSERT_TRUE(IsConnectedTree(level)) << m;
    EXPECT_EQ(level.SegmentCount(), skeleton.SegmentCount() - m);
  }
  // The cheapest merges come first: straight tubes lose most of their nodes for a small move.
  const size_t cheap = MergesWithin(hierarchy, 0.01);
  EXPECT_GT(cheap, skeleton.SegmentCount() / 2);
}

TEST(LineSimplification, RepeatsExactly) {
  const BranchSkeleton skeleton = ExtractBranchSkeleton(test::SyntheticBranches());
  const LineHierarchy a = SimplifyLines(skeleton), b = SimplifyLines(skeleton);
  ASSERT_EQ(a.merges.size(), b.merges.size());
  for (size_t m = 0; m < a.merges.size(); ++m) {
    EXPECT_EQ(a.merges[m].removed, b.merges[m].removed);
    EXPECT_EQ(a.merges[m].kept, b.merges[m].kept);
  }
}

}  // namespace
}  // namespace voltree
