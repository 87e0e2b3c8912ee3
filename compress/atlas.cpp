#include "compress/atlas.h"

#include <algorithm>
#include <cmath>

#include "compress/dxt5.h"
#include "core/error.h"

namespace voltree {

std::vector<uint8_t> LayOutAtlas(const std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texels,
                                 VtreeAtlas& atlas) {
  const size_t texel_count = size_t(texels) * texels;
  const size_t colour_count = rgb.size() / (3 * texel_count);
  const size_t alpha_count = alpha.size() / texel_count;
  const size_t tiles = std::max(colour_count, alpha_count);
  if (tiles == 0) Fail("atlas: empty codebooks");
  atlas.tile_pitch = static_cast<uint32_t>((texels + 3) / 4 * 4);
  atlas.tile_count = static_cast<uint32_t>(tiles);
  atlas.tiles_per_row = static_cast<uint32_t>(std::ceil(std::sqrt(double(tiles))));
  const uint32_t rows = static_cast<uint32_t>((tiles + atlas.tiles_per_row - 1) / atlas.tiles_per_row);
  atlas.width = atlas.tiles_per_row * atlas.tile_pitch;
  atlas.height = rows * atlas.tile_pitch;
  std::vector<uint8_t> image(size_t(atlas.width) * atlas.height * 4, 0);
  for (uint32_t i = 0; i < tiles; ++i) {
    const auto [x0, y0] = atlas.TileOrigin(i);
    for (uint32_t y = 0; y < atlas.tile_pitch; ++y) {
      for (uint32_t x = 0; x < atlas.tile_pitch; ++x) {
        // Padding texels repeat the nearest real texel (clamp to edge).
        const size_t t = std::min<size_t>(y, texels - 1) * texels + std::min<size_t>(x, texels - 1);
        uint8_t* out = image.data() + ((size_t(y0) + y) * atlas.width + x0 + x) * 4;
        if (i < colour_count) std::copy_n(rgb.data() + (i * texel_count + t) * 3, 3, out);
        if (i < alpha_count) out[3] = alpha[i * texel_count + t];
      }
    }
  }
  return image;
}

VtreeAtlas BuildAtlas(const std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texels) {
  VtreeAtlas atlas;
  const std::vector<uint8_t> image = LayOutAtlas(rgb, alpha, texels, atlas);
  atlas.dxt5 = EncodeDxt5(image.data(), int(atlas.width), int(atlas.height));
  return atlas;
}

void FetchBillboard(const std::vector<uint8_t>& decoded_atlas, const VtreeAtlas& atlas, int texels, uint32_t colour,
                    uint32_t alpha, std::vector<uint8_t>& out) {
  const auto [cx, cy] = atlas.TileOrigin(colour);
  const auto [ax, ay] = atlas.TileOrigin(alpha);
  for (int y = 0; y < texels; ++y) {
    for (int x = 0; x < texels; ++x) {
      const uint8_t* c = decoded_atlas.data() + ((size_t(cy) + y) * atlas.width + cx + x) * 4;
      const uint8_t a = decoded_atlas[((size_t(ay) + y) * atlas.width + ax + x) * 4 + 3];
      out.insert(out.end(), {Premultiply(c[0], a), Premultiply(c[1], a), Premultiply(c[2], a), a});
    }
  }
}

}  // namespace voltree
