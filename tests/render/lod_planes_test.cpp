// The Linz 2006 LOD rule: planes orthogonal to the view direction.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "render/lod.h"
#include "render/traversal.h"
#include "render/test_assets.h"

namespace voltree {
namespace {

using test::FullOctree;

LodOptions Planes() {
  LodOptions lod;
  lod.rule = LodRule::kPlanes;
  return lod;
}

// The level drawn over each finest cell (-1 where nothing is drawn).
std::vector<int> CoveringLevels(const OctreeIndex& index, const std::vector<uint32_t>& cells) {
  const uint32_t first = index.FirstCell(index.levels() - 1);
  std::vector<int> covering(index.CellCount() - first, -1);
  for (uint32_t cell : cells) {
    const double half = 0.5 * index.CellSize(index.LevelOf(cell));
    for (uint32_t f = 0; f < covering.size(); ++f)
      if ((index.Center(first + f) - index.Center(cell)).cwiseAbs().maxCoeff() < half)
        covering[f] = index.LevelOf(cell);
  }
  return covering;
}

TEST(LodPlanes, NamesAndPlaneDepths) {
  EXPECT_EQ(LodRuleFromName("planes"), LodRule::kPlanes);
  EXPECT_EQ(LodRuleFromName("screen"), LodRule::kScreen);
  EXPECT_THROW(LodRuleFromName("plane"), Error);
  // Plane of a 0.4 m cell with 4 texels through a 1000 px focal length at 1 px per texel: 100 m.
  EXPECT_DOUBLE_EQ(LodPlaneDepth(Planes(), 0.4, 4, 1000), 100);
  // Just inside the plane the cell refines, just beyond it does not.
  EXPECT_TRUE(ShouldDescend(Planes(), 0, 3, 0.4, 4, 99, 0.35, 1000));
  EXPECT_FALSE(ShouldDescend(Planes(), 0, 3, 0.4, 4, 101, 0.35, 1000));
  EXPECT_FALSE(ShouldDescend(Planes(), 0, 3, 0.4, 4, -5, 0.35, 1000));  // behind the camera plane
}

// A dolly out along the view direction (from outside the tree): no finest cell ever gets a finer
// level, and the sweep spans finest to root.
TEST(LodPlanes, LevelNeverIncreasesWithDistance) {
  const VtreeAsset asset = FullOctree(5);
  const OctreeIndex index(asset);
  const Eigen::Vector3d target(0, 0, 1);
  const Eigen::Vector3d direction = Eigen::Vector3d(-0.8, -0.3, -0.4).normalized();  // eye -> tree
  std::vector<int> previous(index.CellCount() - index.FirstCell(4), 99);
  std::vector<int> finest_seen;
  for (double distance = 2.0; distance < 1500; distance *= 1.25) {
    std::vector<uint32_t> cells;
    TraverseBackToFront(index, {target - distance * direction, 800.0, direction}, Planes(), asset.texels, &cells);
    const std::vector<int> covering = CoveringLevels(index, cells);
    for (size_t f = 0; f < covering.size(); ++f) {
      ASSERT_GE(covering[f], 0) << "finest cell " << f << " not covered at distance " << distance;
      ASSERT_LE(covering[f], previous[f]) << "finest cell " << f << " got finer at distance " << distance;
    }
    previous = covering;
    finest_seen.push_back(*std::max_element(covering.begin(), covering.end()));
  }
  EXPECT_EQ(finest_seen.front(), 4);
  EXPECT_EQ(finest_seen.back(), 0);
}

// Depth along the axis is never more than the Euclidean distance, so planes are at least as fine
// as the screen rule everywhere, and strictly finer for some off-axis cells of a wide view.
TEST(LodPlanes, AtLeastAsFineAsScreenAndFinerOffAxis) {
  const VtreeAsset asset = FullOctree(5);
  const OctreeIndex index(asset);
  const Eigen::Vector3d eye(0, -30, 1), direction(0.6, 0.8, 0);  // the tree is 37 degrees off axis
  // Level 2 texels (1/8 m) at 216 px focal length: 0.9 px at the distance (30 m), 1.1 px at the depth (24 m).
  std::vector<uint32_t> screen_cells, plane_cells;
  TraverseBackToFront(index, {eye, 216.0, direction}, {}, asset.texels, &screen_cells);
  TraverseBackToFront(index, {eye, 216.0, direction}, Planes(), asset.texels, &plane_cells);
  const std::vector<int> screen = CoveringLevels(index, screen_cells), planes = CoveringLevels(index, plane_cells);
  int finer = 0;
  for (size_t f = 0; f < screen.size(); ++f) {
    ASSERT_GE(planes[f], screen[f]) << f;
    finer += planes[f] > screen[f];
  }
  EXPECT_GT(finer, 0);
}

// A forced level draws that level only, and every cell of it, whatever the rule.
TEST(LodPlanes, ForcedLevelDrawsOnlyThatLevel) {
  const VtreeAsset asset = FullOctree(4);
  const OctreeIndex index(asset);
  for (int level = 0; level < 4; ++level) {
    LodOptions lod = Planes();
    lod.forced_level = level;
    std::vector<uint32_t> cells;
    TraverseBackToFront(index, {Eigen::Vector3d(0, -8, 1), 800.0, Eigen::Vector3d(0, 1, 0)}, lod, asset.texels, &cells);
    ASSERT_EQ(cells.size(), asset.levels[level].cells.size());
    for (uint32_t cell : cells) ASSERT_EQ(index.LevelOf(cell), level);
  }
}

TEST(LodPlanes, NeedsAViewDirection) {
  const VtreeAsset asset = FullOctree(2);
  const OctreeIndex index(asset);
  std::vector<uint32_t> cells;
  EXPECT_THROW(TraverseBackToFront(index, {Eigen::Vector3d(0, -8, 1), 800.0}, Planes(), asset.texels, &cells), Error);
}

}  // namespace
}  // namespace voltree
