#include "render/lod.h"

#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "render/traversal.h"
#include "render/test_assets.h"

namespace voltree {
namespace {

using test::FullOctree;

TEST(Lod, TexelPixelsFollowsThePinholeModel) {
  // A 0.4 m cell with 4 texels at 10 m through a 1000 px focal length: 0.1 m * 1000 / 10 = 10 px.
  EXPECT_DOUBLE_EQ(TexelPixels(0.4, 4, 10, 1000), 10);
  LodOptions options;
  EXPECT_TRUE(ShouldDescend(options, 0, 3, 0.4, 4, 10, 0.35, 1000));
  EXPECT_FALSE(ShouldDescend(options, 3, 3, 0.4, 4, 10, 0.35, 1000));   // finest level
  EXPECT_FALSE(ShouldDescend(options, 0, 3, 0.4, 4, 200, 0.35, 1000));  // 0.5 px per texel
  options.forced_level = -2;
  EXPECT_THROW(options.Check(), Error);
}

// Moving the camera straight away from the tree (starting outside the root's bounding sphere, so
// every point of the tree gets farther) never makes the level drawn over any finest cell finer.
TEST(Lod, LevelNeverIncreasesWithDistance) {
  const VtreeAsset asset = FullOctree(5);
  const OctreeIndex index(asset);
  const Eigen::Vector3d centre(0, 0, 1);
  const Eigen::Vector3d direction = Eigen::Vector3d(0.8, 0.3, 0.4).normalized();
  const uint32_t finest_first = index.FirstCell(4), finest_count = index.CellCount() - finest_first;
  std::vector<int> previous(finest_count, 99);
  std::vector<int> levels_seen;
  for (double distance = 2.0; distance < 1500; distance *= 1.25) {
    std::vector<uint32_t> cells;
    TraverseBackToFront(index, {centre + distance * direction, 800.0}, {}, asset.texels, &cells);
    // The level covering each finest cell: walk the emitted cells' boxes.
    std::vector<int> covering(finest_count, -1);
    for (uint32_t cell : cells) {
      const double half = 0.5 * index.CellSize(index.LevelOf(cell));
      for (uint32_t f = 0; f < finest_count; ++f) {
        const Eigen::Vector3d d = (index.Center(finest_first + f) - index.Center(cell)).cwiseAbs();
        if (d.maxCoeff() < half) covering[f] = index.LevelOf(cell);
      }
    }
    for (uint32_t f = 0; f < finest_count; ++f) {
      ASSERT_GE(covering[f], 0) << "finest cell " << f << " not covered at distance " << distance;
      ASSERT_LE(covering[f], previous[f]) << "finest cell " << f << " got finer at distance " << distance;
    }
    previous = covering;
    levels_seen.push_back(*std::max_element(covering.begin(), covering.end()));
  }
  // The sweep really spans the hierarchy: finest level near, root far.
  EXPECT_EQ(levels_seen.front(), 4);
  EXPECT_EQ(levels_seen.back(), 0);
}

}  // namespace
}  // namespace voltree

namespace voltree {
namespace {

// A camera hovering across a cell's refinement threshold: without history the cell flips level
// every frame; with 15% hysteresis it stays where it is. Distances are chosen around the root's
// threshold: texel = 2/4 m, focal 800 -> 1 px at 400 m.
TEST(Lod, HysteresisStopsFlickerAtTheThreshold) {
  const VtreeAsset asset = FullOctree(2);
  const OctreeIndex index(asset);
  const Eigen::Vector3d direction = Eigen::Vector3d(1, 0, 0);
  const Eigen::Vector3d centre(0, 0, 1);
  LodOptions lod;
  auto count_switches = [&](std::vector<uint8_t>* state) {
    int switches = 0;
    size_t previous = 0;
    for (int frame = 0; frame < 10; ++frame) {
      const double distance = frame % 2 ? 395 : 405;  // +-1.3% around the threshold
      std::vector<uint32_t> cells;
      TraverseBackToFront(index, {centre + distance * direction, 800.0}, lod, asset.texels, &cells, state);
      if (frame > 0 && cells.size() != previous) ++switches;
      previous = cells.size();
    }
    return switches;
  };
  EXPECT_EQ(count_switches(nullptr), 9);
  std::vector<uint8_t> state;
  EXPECT_EQ(count_switches(&state), 0);
  // Far beyond the band it still switches: 30% closer refines, and back out coarsens.
  std::vector<uint32_t> cells;
  TraverseBackToFront(index, {centre + 300 * direction, 800.0}, lod, asset.texels, &cells, &state);
  EXPECT_EQ(cells.size(), 8u);
  TraverseBackToFront(index, {centre + 500 * direction, 800.0}, lod, asset.texels, &cells, &state);
  EXPECT_EQ(cells.size(), 1u);
}

}  // namespace
}  // namespace voltree
