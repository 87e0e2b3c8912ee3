#include "render/alpha_extent.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {
namespace {

constexpr int kBlockBytes = 16;  // DXT5: 8 bytes of alpha, then 8 of colour

// Bit t of the result: texel t (row-major) of a DXT5 block may have a non-zero alpha.
uint16_t NonZeroAlphaTexels(const uint8_t* block) {
  const int a0 = block[0], a1 = block[1];
  // The palette entries that are exactly 0: the endpoints, and in six-value mode (a0 <= a1) code 6;
  // the interpolants are 0 only between two zero endpoints.
  bool zero[8] = {a0 == 0, a1 == 0};
  for (int code = 2; code < 8; ++code) zero[code] = a0 == 0 && a1 == 0;
  if (a0 <= a1) zero[6] = true, zero[7] = false;
  uint64_t codes = 0;  // 16 three-bit codes, little-endian
  for (int i = 0; i < 6; ++i) codes |= uint64_t(block[2 + i]) << (8 * i);
  uint16_t mask = 0;
  for (int t = 0; t < 16; ++t)
    if (!zero[(codes >> (3 * t)) & 7]) mask |= uint16_t(1u << t);
  return mask;
}

// Half-texel bounds of texels [first, last] read by clamped bilinear filtering in a row of n.
uint8_t LowerBound(int first) { return uint8_t(std::max(0, 2 * first - 1)); }
uint8_t UpperBound(int last, int n) { return uint8_t(std::min(2 * n, 2 * last + 3)); }

}  // namespace

std::vector<AlphaExtent> AlphaTileExtents(const VtreeAtlas& atlas, int texels) {
  if (texels < 1 || texels > 127) Fail("alpha extents: billboards of ", texels, " texels (expected 1..127)");
  if (atlas.width % 4 || atlas.height % 4 || atlas.dxt5.size() != size_t(atlas.width) * atlas.height)
    Fail("alpha extents: bad atlas ", atlas.width, "x", atlas.height, " with ", atlas.dxt5.size(), " bytes");
  if (atlas.tile_count > 0 && (atlas.tiles_per_row == 0 || uint32_t(texels) > atlas.tile_pitch))
    Fail("alpha extents: tiles of ", atlas.tile_pitch, " texels cannot hold billboards of ", texels);
  const uint32_t blocks_per_row = atlas.width / 4;
  std::vector<AlphaExtent> extents(atlas.tile_count);
  for (uint32_t tile = 0; tile < atlas.tile_count; ++tile) {
    const auto [x0, y0] = atlas.TileOrigin(tile);
    if (x0 + texels > atlas.width || y0 + texels > atlas.height)
      Fail("alpha extents: tile ", tile, " lies outside the ", atlas.width, "x", atlas.height, " atlas");
    int min_s = texels, max_s = -1, min_t = texels, max_t = -1;
    for (int t = 0; t < texels; ++t)
      for (int s = 0; s < texels; ++s) {
        const uint32_t x = x0 + s, y = y0 + t;
        const uint8_t* block = atlas.dxt5.data() + (size_t(y / 4) * blocks_per_row + x / 4) * kBlockBytes;
        if (!(NonZeroAlphaTexels(block) >> ((y % 4) * 4 + x % 4) & 1)) continue;
        min_s = std::min(min_s, s), max_s = std::max(max_s, s);
        min_t = std::min(min_t, t), max_t = std::max(max_t, t);
      }
    if (max_s < 0) continue;  // all zero: the empty extent
    extents[tile] = {LowerBound(min_s), LowerBound(min_t), UpperBound(max_s, texels), UpperBound(max_t, texels)};
  }
  return extents;
}

}  // namespace voltree
