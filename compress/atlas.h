// The codebook atlas (Linz 2006, 4.1.2): tile i holds colour codeword i in RGB and alpha codeword
// i in A, so one DXT5 texture serves both codebooks; a billboard samples RGB from tile `colour`
// and A from tile `alpha`. Tiles are n x n texels padded to a multiple of 4 (one DXT block for
// n = 4, so no block mixes two codewords) and laid out in a square-ish grid. Padding repeats the
// edge texels, which keeps the DXT endpoint fit on the real texels and lets lookups clamp inside.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vtree.h"

namespace voltree {

// `rgb`: K_c x n*n x 3 straight sRGB8; `alpha`: K_a x n*n. Returns the uncompressed RGBA8 image
// and fills the layout fields of `atlas` (not its DXT5 data).
std::vector<uint8_t> LayOutAtlas(const std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texels,
                                 VtreeAtlas& atlas);

// LayOutAtlas then DXT5 through libsquish.
VtreeAtlas BuildAtlas(const std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texels);

// What the renderer sees for one billboard: straight RGB of tile `colour`, A of tile `alpha`,
// fetched from a decoded (RGBA8) atlas, then premultiplied. Appends n*n RGBA8 texels to `out`.
void FetchBillboard(const std::vector<uint8_t>& decoded_atlas, const VtreeAtlas& atlas, int texels, uint32_t colour,
                    uint32_t alpha, std::vector<uint8_t>& out);

// Premultiplies straight colour by alpha, rounding: what the shader's rgb * a yields in 8 bits.
inline uint8_t Premultiply(uint8_t straight, uint8_t alpha) {
  return static_cast<uint8_t>((straight * alpha + 127) / 255);
}

}  // namespace voltree
