// The renderer's image formation on the CPU, for one level of an uncompressed volume.
//
// The GPU draws, for every cell of the level back to front (volume_order.h), the billboards of two
// input views blended: each pixel's ray meets view k's billboard plane (through the cell centre,
// facing view k), the texture is sampled bilinearly there (clamped half a texel inside, so a tile
// never bleeds into its neighbour), the two samples are summed with the views' weights and the
// result is composited with the over operator (premultiplied). RasterizeLevel records, for every
// pixel, which texels each cell contributes and with which weights: a sparse, fixed description of
// the image that the billboard fit differentiates and the error budget composites.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/volume.h"

namespace voltree {

// The input views whose billboards are drawn, as the renderer picks them (render/view_selection.h).
struct ViewBlend {
  int first = 0, second = -1;  // second < 0: one view
  float first_weight = 1, second_weight = 0;
};

// One view's billboard seen through one pixel: a bilinear tap.
struct BillboardTap {
  uint32_t texel = 0;    // global index (billboard * n * n + row * n + col) of the top-left texel
  float fx = 0, fy = 0;  // bilinear weights of the right column and of the lower row
  float weight = 0;      // the view's blend weight (0: this view shows nothing here)
};

// One cell seen through one pixel.
struct BillboardLayer {
  std::array<BillboardTap, 2> taps;
};

// Per pixel (row-major), the layers back to front.
struct LayerImage {
  int width = 0, height = 0, texels = 0;  // texels: n, billboards are n x n
  std::vector<uint32_t> offsets;          // width * height + 1; pixel p's layers: [offsets[p], offsets[p + 1])
  std::vector<BillboardLayer> layers;
};

// Rasterizes level `level` of `volume` (billboards of the blend's views) for `camera`; billboards
// have side `billboard_scale` x cell edge, as reconstruct made them and render draws them.
LayerImage RasterizeLevel(const Volume& volume, int level, const View& camera, const ViewBlend& blend,
                          double billboard_scale);

// Premultiplied RGBA of one layer from `texels` (premultiplied RGBA, four values per texel,
// indexed as BillboardTap::texel); `scale` maps stored values to [0, 1]. Inline: the fit's inner
// loop calls it once per layer of every pixel.
template <typename Texel>
inline std::array<float, 4> SampleLayer(const BillboardLayer& layer, const Texel* texels, int n, float scale = 1) {
  std::array<float, 4> sum{0, 0, 0, 0};
  const size_t dx = n > 1 ? 4 : 0, dy = n > 1 ? size_t(4) * n : 0;
  for (const BillboardTap& tap : layer.taps) {
    if (tap.weight == 0) continue;
    const Texel* t = texels + size_t(tap.texel) * 4;
    const float w00 = (1 - tap.fx) * (1 - tap.fy), w10 = tap.fx * (1 - tap.fy), w01 = (1 - tap.fx) * tap.fy,
                w11 = tap.fx * tap.fy;
    for (int c = 0; c < 4; ++c)
      sum[c] += scale * tap.weight *
                (w00 * float(t[c]) + w10 * float(t[dx + c]) + w01 * float(t[dy + c]) + w11 * float(t[dx + dy + c]));
  }
  return sum;
}

// The composited image (premultiplied RGBA in [0, 1] over transparent black).
ImageF CompositeLayers(const LayerImage& image, const std::vector<float>& texels);
// The same from a level's 8-bit texels (VolumeLevel::texels), without a float copy of them all.
ImageF CompositeLayers(const LayerImage& image, const std::vector<uint8_t>& texels);

// The level's texels as floats in [0, 1] (premultiplied RGBA, four per texel).
std::vector<float> TexelsAsFloat(const VolumeLevel& level);

}  // namespace voltree
