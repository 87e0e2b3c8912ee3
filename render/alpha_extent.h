// Where each atlas tile's alpha can be non-zero, so that a billboard's quad covers only the part
// of its square that its texture can draw (overdraw: on a software rasterizer the time follows
// the fragments shaded, and a leaf's 4x4 texels rarely fill their square).
//
// A texel counts as non-zero unless its DXT5 alpha is 0 in exact arithmetic (an endpoint of 0,
// the explicit 0 of the six-value mode, or two zero endpoints), which no decoder rounds up:
// decoders that round a small interpolant down to 0 only make the extent conservative. With
// bilinear filtering clamped half a texel inside the tile (the renderer's fetch), texel i of an
// n-texel row is read for s * n in (i - 0.5, i + 1.5), so the extent grows half a texel each side,
// to the tile's edge where it touches it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vtree.h"

namespace voltree {

// A tile's extent in half-texel units of its billboard square: s in [lo_s, hi_s] / (2n), t (down)
// in [lo_t, hi_t] / (2n). Empty when every texel's alpha is 0.
struct AlphaExtent {
  uint8_t lo_s = 0, lo_t = 0, hi_s = 0, hi_t = 0;
  bool Empty() const { return hi_s <= lo_s; }
  // lo_s | lo_t << 8 | hi_s << 16 | hi_t << 24, as the renderer's shader reads it.
  uint32_t Packed() const { return uint32_t(lo_s) | uint32_t(lo_t) << 8 | uint32_t(hi_s) << 16 | uint32_t(hi_t) << 24; }
};

// Per atlas tile (index = tile), from the atlas's DXT5 blocks; `texels` is the billboard side n
// (1..127). Throws Error when the atlas's size does not match its blocks.
std::vector<AlphaExtent> AlphaTileExtents(const VtreeAtlas& atlas, int texels);

}  // namespace voltree
