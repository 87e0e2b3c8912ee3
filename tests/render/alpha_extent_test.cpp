#include "render/alpha_extent.h"

#include <gtest/gtest.h>

#include <array>

#include "core/error.h"

namespace voltree {
namespace {

// A DXT5 block with alpha endpoints a0, a1 and the 3-bit alpha code of each texel (row-major).
std::array<uint8_t, 16> AlphaBlock(uint8_t a0, uint8_t a1, const std::array<int, 16>& codes) {
  std::array<uint8_t, 16> block{};
  block[0] = a0, block[1] = a1;
  uint64_t bits = 0;
  for (int t = 0; t < 16; ++t) bits |= uint64_t(codes[t]) << (3 * t);
  for (int i = 0; i < 6; ++i) block[2 + i] = uint8_t(bits >> (8 * i));
  return block;
}

VtreeAtlas OneRowAtlas(const std::vector<std::array<uint8_t, 16>>& blocks) {
  VtreeAtlas atlas;
  atlas.width = uint32_t(4 * blocks.size()), atlas.height = 4;
  atlas.tiles_per_row = atlas.tile_count = uint32_t(blocks.size());
  for (const auto& block : blocks) atlas.dxt5.insert(atlas.dxt5.end(), block.begin(), block.end());
  return atlas;
}

TEST(AlphaTileExtents, BoundTheNonZeroTexelsHalfATexelWider) {
  std::array<int, 16> one_texel{};  // code 0 (a0 = 0) everywhere but texel (s 2, t 1): code 1 (a1 = 200)
  one_texel[1 * 4 + 2] = 1;
  std::array<int, 16> top_rows{};  // rows 0 and 1: code 0 (a0 = 255); rows 2, 3: code 1 (a1 = 0)
  for (int t = 8; t < 16; ++t) top_rows[t] = 1;
  const VtreeAtlas atlas = OneRowAtlas({AlphaBlock(0, 200, one_texel), AlphaBlock(255, 0, top_rows),
                                        AlphaBlock(0, 0, std::array<int, 16>{}), AlphaBlock(255, 255, {})});
  const std::vector<AlphaExtent> extents = AlphaTileExtents(atlas, 4);
  ASSERT_EQ(extents.size(), 4u);
  // Texel 2 of 4 is read for s * 4 in (1.5, 3.5): half texels 3..7 of 8.
  EXPECT_EQ(extents[0].lo_s, 3);
  EXPECT_EQ(extents[0].hi_s, 7);
  EXPECT_EQ(extents[0].lo_t, 1);
  EXPECT_EQ(extents[0].hi_t, 5);
  // Touching the tile's edge: the filter is clamped there, so the extent ends at the edge.
  EXPECT_EQ(extents[1].lo_s, 0);
  EXPECT_EQ(extents[1].hi_s, 8);
  EXPECT_EQ(extents[1].lo_t, 0);
  EXPECT_EQ(extents[1].hi_t, 5);
  EXPECT_TRUE(extents[2].Empty());  // both endpoints 0: every code is 0
  EXPECT_FALSE(extents[3].Empty());
  EXPECT_EQ(extents[3].Packed(), 0u | 0u << 8 | 8u << 16 | 8u << 24);
}

TEST(AlphaTileExtents, SixValueModeHasAnExplicitZeroAndInterpolantsCountAsNonZero) {
  std::array<int, 16> codes{};
  codes.fill(6);  // a0 <= a1: code 6 is 0, code 7 is 255
  codes[15] = 7;
  std::array<int, 16> interpolant{};
  interpolant.fill(0);  // a0 = 0
  interpolant[5] = 2;   // (4 * 0 + 1 * 3) / 5 rounds to 1 or 0, by decoder: counted non-zero
  const std::vector<AlphaExtent> extents =
      AlphaTileExtents(OneRowAtlas({AlphaBlock(10, 20, codes), AlphaBlock(0, 3, interpolant)}), 4);
  EXPECT_EQ(extents[0].lo_s, 5);  // only texel (3, 3)
  EXPECT_EQ(extents[0].lo_t, 5);
  EXPECT_EQ(extents[0].hi_s, 8);
  EXPECT_EQ(extents[0].hi_t, 8);
  EXPECT_EQ(extents[1].lo_s, 1);  // texel (1, 1)
  EXPECT_EQ(extents[1].hi_s, 5);
}

TEST(AlphaTileExtents, SmallerBillboardsThanTheirTilesAndBadAtlasesAreNamed) {
  std::array<int, 16> codes{};
  codes.fill(1);         // a1 = 0
  codes[3 * 4 + 3] = 0;  // texel (3, 3): a0 = 90, outside a 3-texel billboard
  codes[0] = 0;
  const VtreeAtlas atlas = OneRowAtlas({AlphaBlock(90, 0, codes)});
  const AlphaExtent extent = AlphaTileExtents(atlas, 3)[0];
  EXPECT_EQ(extent.lo_s, 0);
  EXPECT_EQ(extent.hi_s, 3);  // texel 0 of 3 read up to s * 3 = 1.5
  VtreeAtlas short_blocks = atlas;
  short_blocks.dxt5.pop_back();
  EXPECT_THROW(AlphaTileExtents(short_blocks, 4), Error);
  EXPECT_THROW(AlphaTileExtents(atlas, 5), Error);  // larger than the 4-texel tiles
  EXPECT_THROW(AlphaTileExtents(atlas, 0), Error);
}

}  // namespace
}  // namespace voltree
