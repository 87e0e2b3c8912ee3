#include "render/traversal.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "render/lod.h"

namespace voltree {
namespace {

// A random octree: every kept cell of a level keeps each child with probability `keep`.
VtreeAsset RandomTree(uint32_t seed, int levels, int branching, double keep) {
  std::mt19937 random(seed);
  std::bernoulli_distribution kept(keep);
  VtreeAsset asset;
  asset.origin = Eigen::Vector3d(-1, -1, 0);
  asset.size = 2;
  asset.branching = branching;
  asset.texels = 4;
  VtreeLevel root;
  root.resolution = 1;
  root.cells.push_back({0, 0, 0});
  asset.levels.push_back(root);
  for (int l = 1; l < levels; ++l) {
    VtreeLevel level;
    level.resolution = asset.levels.back().resolution * branching;
    for (const auto& parent : asset.levels.back().cells)
      for (int x = 0; x < branching; ++x)
        for (int y = 0; y < branching; ++y)
          for (int z = 0; z < branching; ++z)
            if (kept(random))
              level.cells.push_back({uint16_t(parent[0] * branching + x), uint16_t(parent[1] * branching + y),
                                     uint16_t(parent[2] * branching + z)});
    asset.levels.push_back(level);
  }
  return asset;
}

struct Box {
  Eigen::Vector3d min, max;
};
Box CellBox(const OctreeIndex& index, uint32_t cell) {
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5 * index.CellSize(index.LevelOf(cell)));
  return {index.Center(cell) - half, index.Center(cell) + half};
}

// `earlier` (drawn first) is in front of `later` when they are disjoint and the eye is strictly
// on `earlier`'s side of every axis along which they are separated: then a ray from the eye can
// cross `earlier` before `later`, and never the other way round.
bool InFront(const Box& earlier, const Box& later, const Eigen::Vector3d& eye) {
  const double eps = 1e-9;
  bool separated = false;
  for (int k = 0; k < 3; ++k) {
    if (earlier.max[k] <= later.min[k] + eps) {
      separated = true;
      if (!(eye[k] < earlier.max[k] - eps)) return false;
    } else if (later.max[k] <= earlier.min[k] + eps) {
      separated = true;
      if (!(eye[k] > earlier.min[k] + eps)) return false;
    }
  }
  return separated;
}

TEST(Traversal, BackToFrontOnRandomOctreesAndCameras) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  int pairs_checked = 0, violations = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int branching = trial % 3 == 2 ? 3 : 2;
    const VtreeAsset asset = RandomTree(100 + trial, branching == 3 ? 3 : 4, branching, 0.45);
    const OctreeIndex index(asset);
    for (int c = 0; c < 4; ++c) {
      // Some cameras inside the root cube, most outside.
      const Eigen::Vector3d eye = c == 0 ? Eigen::Vector3d(0.3 * coordinate(random), 0.3 * coordinate(random), 1.0)
                                         : Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
      LodOptions lod;
      lod.max_texel_pixels = c == 3 ? 0.05 : 1.0;  // coarse mixes of levels too
      std::vector<uint32_t> cells;
      TraverseBackToFront(index, {eye, 100.0}, lod, asset.texels, &cells);
      ASSERT_FALSE(cells.empty());
      for (size_t i = 0; i < cells.size(); ++i)
        for (size_t j = i + 1; j < cells.size(); ++j) {
          ++pairs_checked;
          if (InFront(CellBox(index, cells[i]), CellBox(index, cells[j]), eye)) ++violations;
        }
    }
  }
  EXPECT_GT(pairs_checked, 10000);
  EXPECT_EQ(violations, 0);
}

// The check itself must be able to fail: the reversed order of a real traversal violates it.
TEST(Traversal, ReversedOrderIsDetected) {
  const VtreeAsset asset = RandomTree(3, 3, 2, 0.8);
  const OctreeIndex index(asset);
  const Eigen::Vector3d eye(5, 0.5, 1.2);
  LodOptions lod;
  lod.forced_level = 2;
  std::vector<uint32_t> cells;
  TraverseBackToFront(index, {eye, 100.0}, lod, asset.texels, &cells);
  int violations = 0;
  for (size_t i = 0; i < cells.size(); ++i)
    for (size_t j = i + 1; j < cells.size(); ++j)
      violations += InFront(CellBox(index, cells[j]), CellBox(index, cells[i]), eye);
  EXPECT_GT(violations, 0);
}

TEST(Traversal, ForcedLevelEmitsOnlyThatLevelAndEveryCellOnce) {
  const VtreeAsset asset = RandomTree(11, 4, 2, 0.5);
  const OctreeIndex index(asset);
  for (int level = 0; level < 4; ++level) {
    LodOptions lod;
    lod.forced_level = level;
    std::vector<uint32_t> cells;
    TraverseBackToFront(index, {Eigen::Vector3d(3, -2, 1), 1000.0}, lod, asset.texels, &cells);
    EXPECT_EQ(cells.size(), asset.levels[level].cells.size()) << "level " << level;
    const std::set<uint32_t> unique(cells.begin(), cells.end());
    EXPECT_EQ(unique.size(), cells.size());
    for (uint32_t cell : cells) EXPECT_EQ(index.LevelOf(cell), level);
  }
}

TEST(Traversal, ChildrenAndBillboardsAreLinked) {
  VtreeAsset asset = RandomTree(5, 3, 2, 0.6);
  asset.levels[1].billboards = {{0, 2, 0, 0}, {0, 5, 1, 1}};
  const OctreeIndex index(asset);
  const uint32_t cell = index.FirstCell(1);
  EXPECT_EQ(index.FindBillboard(cell, 5), 1u);
  EXPECT_EQ(index.FindBillboard(cell, 2), 0u);
  EXPECT_EQ(index.FindBillboard(cell, 3), OctreeIndex::kNone);
  size_t children = 0;
  for (uint32_t c = index.FirstCell(1); c < index.FirstCell(2); ++c)
    children += size_t(index.ChildrenEnd(c) - index.ChildrenBegin(c));
  EXPECT_EQ(children, asset.levels[2].cells.size());
}

}  // namespace
}  // namespace voltree
