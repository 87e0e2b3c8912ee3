#include "reconstruct/matte_stats.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace voltree {

uint8_t CarveThreshold8(double carve_alpha) { return uint8_t(std::clamp(std::floor(carve_alpha * 255.0), 0.0, 254.0)); }

PixelBox CoveredPixels(double min_x, double min_y, double max_x, double max_y) {
  PixelBox box;
  const double cx = 0.5 * (min_x + max_x), cy = 0.5 * (min_y + max_y);
  // A pixel counts when its centre lies inside; never less than the pixel holding the centre.
  box.x0 = int(std::min(std::ceil(min_x - 0.5), std::floor(cx)));
  box.y0 = int(std::min(std::ceil(min_y - 0.5), std::floor(cy)));
  box.x1 = int(std::max(std::ceil(max_x - 0.5), std::floor(cx) + 1));
  box.y1 = int(std::max(std::ceil(max_y - 0.5), std::floor(cy) + 1));
  return box;
}

MatteStats::MatteStats(const Image8& matte, uint8_t occupied_above) : width_(matte.width), height_(matte.height) {
  if (matte.channels != 1) Fail("matte must have 1 channel, got ", matte.channels);
  const size_t stride = size_t(width_) + 1;
  alpha_.assign(stride * (height_ + 1), 0);
  occupied_.assign(stride * (height_ + 1), 0);
  int64_t opaque = 0;
  for (int y = 0; y < height_; ++y) {
    uint64_t row_alpha = 0;
    uint32_t row_occupied = 0;
    for (int x = 0; x < width_; ++x) {
      const uint8_t a = matte.at(x, y);
      max_alpha_ = std::max(max_alpha_, a);
      opaque += a >= 250;
      row_alpha += a;
      row_occupied += a > occupied_above;
      alpha_[(y + 1) * stride + x + 1] = alpha_[y * stride + x + 1] + row_alpha;
      occupied_[(y + 1) * stride + x + 1] = occupied_[y * stride + x + 1] + row_occupied;
    }
  }
  opaque_fraction_ = width_ * height_ > 0 ? double(opaque) / (double(width_) * height_) : 0;
}

PixelBox MatteStats::Clip(const PixelBox& b) const {
  return {std::max(b.x0, 0), std::max(b.y0, 0), std::min(b.x1, width_), std::min(b.y1, height_)};
}

double MatteStats::MeanAlpha(const PixelBox& box) const {
  const PixelBox b = Clip(box);
  if (b.empty()) return -1;
  const size_t s = size_t(width_) + 1;
  const uint64_t sum =
      alpha_[b.y1 * s + b.x1] - alpha_[b.y0 * s + b.x1] - alpha_[b.y1 * s + b.x0] + alpha_[b.y0 * s + b.x0];
  return double(sum) / (255.0 * double(b.area()));
}

int64_t MatteStats::Occupied(const PixelBox& b) const {
  const size_t s = size_t(width_) + 1;
  return int64_t(occupied_[b.y1 * s + b.x1]) - occupied_[b.y0 * s + b.x1] - occupied_[b.y1 * s + b.x0] +
         occupied_[b.y0 * s + b.x0];
}

ColourStats::ColourStats(const Image8& rgba) : width_(rgba.width), height_(rgba.height) {
  if (rgba.channels != 4) Fail("foreground must be RGBA, got ", rgba.channels, " channels");
  const size_t stride = size_t(width_) + 1;
  sums_.assign(stride * (height_ + 1) * 4, 0);
  for (int y = 0; y < height_; ++y) {
    std::array<uint64_t, 4> row{0, 0, 0, 0};
    for (int x = 0; x < width_; ++x)
      for (int c = 0; c < 4; ++c) {
        row[c] += rgba.at(x, y, c);
        sums_[((y + 1) * stride + x + 1) * 4 + c] = sums_[(y * stride + x + 1) * 4 + c] + row[c];
      }
  }
}

std::array<double, 3> ColourStats::MeanStraightColour(const PixelBox& box) const {
  const PixelBox b{std::max(box.x0, 0), std::max(box.y0, 0), std::min(box.x1, width_), std::min(box.y1, height_)};
  if (b.empty()) return {0, 0, 0};
  const size_t s = size_t(width_) + 1;
  std::array<uint64_t, 4> sum;
  for (int c = 0; c < 4; ++c)
    sum[c] = sums_[(b.y1 * s + b.x1) * 4 + c] - sums_[(b.y0 * s + b.x1) * 4 + c] - sums_[(b.y1 * s + b.x0) * 4 + c] +
             sums_[(b.y0 * s + b.x0) * 4 + c];
  if (sum[3] == 0) return {0, 0, 0};
  std::array<double, 3> colour;
  for (int c = 0; c < 3; ++c) colour[c] = std::min(255.0, 255.0 * double(sum[c]) / double(sum[3]));
  return colour;
}

}  // namespace voltree
