// Box statistics of one view's matte and foreground in O(1) per box: summed-area tables of 8-bit
// sums (exact integers, so results do not depend on summation order). This is the box filter
// that averages alpha as transmittance over a ray's footprint at any level.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace voltree {

// A pixel rectangle [x0, x1) x [y0, y1).
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int64_t area() const { return empty() ? 0 : int64_t(x1 - x0) * (y1 - y0); }
};

// The pixels covered by the continuous rectangle [min, max) in pixel coordinates (pixel (x, y)
// covers [x, x+1) x [y, y+1)); at least the pixel containing the centre.
PixelBox CoveredPixels(double min_x, double min_y, double max_x, double max_y);

// The 8-bit alpha at or below which a pixel is empty for carving, from carve_alpha in [0, 1).
uint8_t CarveThreshold8(double carve_alpha);

class MatteStats {
 public:
  MatteStats() = default;
  // `matte`: 1 channel 8-bit alpha. Pixels with alpha > occupied_above count as occupied.
  MatteStats(const Image8& matte, uint8_t occupied_above);

  int width() const { return width_; }
  int height() const { return height_; }
  PixelBox Clip(const PixelBox& box) const;
  // Mean alpha in [0, 1] over the box clipped to the image; -1 when nothing is left.
  double MeanAlpha(const PixelBox& box) const;
  // Occupied pixels in the box (which must be inside the image).
  int64_t Occupied(const PixelBox& box) const;
  uint8_t max_alpha() const { return max_alpha_; }
  double opaque_fraction() const { return opaque_fraction_; }  // share of pixels with alpha >= 250

 private:
  int width_ = 0, height_ = 0;
  std::vector<uint64_t> alpha_;     // (w+1) x (h+1) summed-area table of alpha
  std::vector<uint32_t> occupied_;  // (w+1) x (h+1) summed-area table of occupied pixels
  uint8_t max_alpha_ = 0;
  double opaque_fraction_ = 0;
};

// Summed-area tables of a premultiplied RGBA foreground, for texel colours.
class ColourStats {
 public:
  explicit ColourStats(const Image8& rgba);
  // Straight (un-premultiplied) sRGB colour in [0, 255] averaged over the box; black when the
  // box holds no alpha.
  std::array<double, 3> MeanStraightColour(const PixelBox& box) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<uint64_t> sums_;  // (w+1) x (h+1) x 4
};

}  // namespace voltree
