#include "lod/point_line_hierarchy.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "lod/branch_skeleton.h"
#include "lod/leaf_separation.h"
#include "lod/synthetic_branches.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

PointLineHierarchy Build(const TreeMesh& mesh, uint64_t seed) {
  PointLineOptions options;
  options.seed = seed;
  return BuildPointLineHierarchy(mesh, SeparateLeaves(mesh), ExtractBranchSkeleton(mesh), options);
}

TEST(PointLineHierarchy, APrefixOfKHasExactlyK) {
  const PointLineHierarchy all = Build(test::SyntheticBranches(true), 3);
  ASSERT_EQ(all.points.size(), 4u * 2 * 2);  // 4 cards of 2 triangles, 2 points each (no texture: all land)
  ASSERT_GT(all.lines.size(), 20u);
  for (size_t k : {size_t{0}, size_t{1}, size_t{5}, all.points.size()}) {
    const PointLineHierarchy prefix = PointLinePrefix(all, k, k);
    EXPECT_EQ(prefix.points.size(), k);
    EXPECT_EQ(prefix.lines.size(), k);
    for (size_t i = 0; i < k; ++i) EXPECT_EQ(prefix.points[i].position, all.points[i].position);
  }
  // Asking for more than there is gives all of it.
  EXPECT_EQ(PointLinePrefix(all, 1000, 1000).lines.size(), all.lines.size());
  // Lines: the largest projected area first.
  for (size_t i = 1; i < all.lines.size(); ++i)
    EXPECT_GE((all.lines[i - 1].b - all.lines[i - 1].a).norm() * all.lines[i - 1].width + 1e-9f,
              (all.lines[i].b - all.lines[i].a).norm() * all.lines[i].width);
}

TEST(PointLineHierarchy, PointsCoverTheLeavesUniformlyAndRepeatWithTheSeed) {
  const TreeMesh mesh = test::SyntheticFoliage(200, 0.05f);
  const PointLineHierarchy a = Build(mesh, 5), b = Build(mesh, 5), c = Build(mesh, 6);
  ASSERT_EQ(a.points.size(), 800u);
  EXPECT_NEAR(a.leaf_area, 200 * 0.05 * 0.05, 1e-6);
  bool same = true, different = false;
  for (size_t i = 0; i < a.points.size(); ++i) {
    same = same && a.points[i].position == b.points[i].position;
    different = different || a.points[i].position != c.points[i].position;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(different);
  // A random order: the first half holds about half of each side of the foliage.
  int low = 0;
  for (size_t i = 0; i < 400; ++i) low += a.points[i].position.x() < 0.5f;
  EXPECT_NEAR(low, 200, 40);
}

TEST(PointLineHierarchy, TheScreenSizeAsksForPointsOrThePolygons) {
  const TreeMesh mesh = test::SyntheticFoliage(200, 0.05f);
  const PointLineHierarchy all = Build(mesh, 1);
  const PointLineOptions options;
  // 0.5 m^2 of leaves, half of it facing the camera: 0.25 * ppu^2 pixels, one point each.
  const PointLineLevel small = PointLineLevelFor(all, 20, options);
  EXPECT_FALSE(small.polygons);
  EXPECT_EQ(small.points, 100u);
  EXPECT_NEAR(small.point_pixels, std::sqrt(1.3), 1e-3);
  EXPECT_TRUE(PointLineLevelFor(all, 200, options).polygons);  // 10 000 points asked, 800 sampled
  EXPECT_THROW(PointLineLevelFor(all, 0, options), Error);
}

TEST(PointLineHierarchy, AMeshWithoutLeavesGetsLinesOnlyAndOneWithoutBarkPointsOnly) {
  const PointLineHierarchy bark = Build(test::SyntheticBranches(false), 1);
  EXPECT_TRUE(bark.points.empty());
  EXPECT_FALSE(bark.lines.empty());
  const PointLineLevel level = PointLineLevelFor(bark, 100, PointLineOptions{});
  EXPECT_FALSE(level.polygons);
  EXPECT_EQ(level.points, 0u);
  EXPECT_GT(level.lines, 0u);

  TreeMesh leaves_only = test::SyntheticFoliage(20, 0.05f);
  leaves_only.groups.erase(leaves_only.groups.begin());  // the bark triangle
  const PointLineHierarchy leaves = Build(leaves_only, 1);
  EXPECT_EQ(leaves.points.size(), 80u);
  EXPECT_TRUE(leaves.lines.empty());
}

TEST(PointLineHierarchy, BadOptionsAreNamed) {
  PointLineOptions options;
  options.sample_distance = 0;
  try {
    options.Check();
    FAIL();
  } catch (const OptionError& error) {
    EXPECT_EQ(error.field(), "PointLineOptions.sample_distance");
  }
}

}  // namespace
}  // namespace voltree
