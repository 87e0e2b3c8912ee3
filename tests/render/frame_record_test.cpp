#include "render/frame_record.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace voltree {
namespace {

// Levels 0..2 of an octree: the root, two children, and three grandchildren under the first child
// only, so the second child is a leaf one level above the finest.
VtreeAsset ThreeLevels() {
  VtreeAsset asset;
  asset.levels.resize(3);
  asset.levels[0].resolution = 1, asset.levels[0].cells = {{0, 0, 0}};
  asset.levels[1].resolution = 2, asset.levels[1].cells = {{0, 0, 0}, {1, 1, 1}};
  asset.levels[2].resolution = 4, asset.levels[2].cells = {{0, 1, 0}, {1, 1, 1}, {1, 0, 0}};
  return asset;
}

TEST(FrameRecord, CellCoordinatesPackTenBitsEachLevelByLevel) {
  VtreeAsset asset = ThreeLevels();
  asset.levels.resize(11);
  for (int l = 3; l < 11; ++l) asset.levels[l].resolution = 1u << l;
  asset.levels[10].cells = {{1023, 5, 1000}};
  const std::vector<uint32_t> codes = PackCellCoordinates(asset);
  ASSERT_EQ(codes.size(), 7u);
  EXPECT_EQ(codes[0], 0u);
  EXPECT_EQ(codes[2], 1u | 1u << 10 | 1u << 20);  // level 1 (1, 1, 1)
  EXPECT_EQ(codes[3], 0u | 1u << 10);             // level 2 (0, 1, 0)
  EXPECT_EQ(codes[6], 1023u | 5u << 10 | 1000u << 20);
}

TEST(FrameRecord, ALevelFinerThanTheRendererDrawsIsNamed) {
  VtreeAsset asset = ThreeLevels();
  asset.levels.resize(12);
  for (int l = 3; l < 12; ++l) asset.levels[l].resolution = 1u << l;
  try {
    PackCellCoordinates(asset);
    FAIL() << "level 11 has 2048 cells per axis";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("level 11 has 2048 cells per axis"), std::string::npos) << error.what();
  }
}

TEST(FrameRecord, HoldsTheTilesOfEachPresentBillboardAndTheLevel) {
  const VtreeBillboard a{7, 3, 511, 65535}, b{7, 4, 2, 9};
  const FrameRecord both = MakeFrameRecord(42, 6, &a, &b);
  EXPECT_EQ(both[0], 42u);
  EXPECT_EQ(both[1], 511u | 65535u << 16);
  EXPECT_EQ(both[2], 2u | 9u << 16);
  EXPECT_EQ(both[3], 6u | 3u << 8);
  const FrameRecord only_b = MakeFrameRecord(42, 0, nullptr, &b);
  EXPECT_EQ(only_b[1], 0u);
  EXPECT_EQ(only_b[3], 2u << 8);
}

TEST(FrameRecord, AFrameNeedsAtMostOneRecordPerLeafCell) {
  // Leaves: the second level-1 cell and the three finest cells.
  EXPECT_EQ(ThreeLevels().LeafCellCount(), 4u);
  VtreeAsset tri_grid = ThreeLevels();
  tri_grid.branching = 3;
  tri_grid.levels[1].resolution = 3, tri_grid.levels[2].resolution = 9;
  tri_grid.levels[2].cells = {{2, 2, 2}, {3, 3, 3}};  // under (0,0,0) and (1,1,1)
  EXPECT_EQ(tri_grid.LeafCellCount(), 2u);
  EXPECT_EQ(VtreeAsset{}.LeafCellCount(), 0u);
}

}  // namespace
}  // namespace voltree
