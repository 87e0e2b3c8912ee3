#include "core/image_resample.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.h"

namespace voltree {
namespace {

// Per output index, the (input index, weight) pairs of the input interval it covers.
std::vector<std::vector<std::pair<int, float>>> AreaWeights(int from, int to) {
  std::vector<std::vector<std::pair<int, float>>> out(to);
  const double step = double(from) / to;
  for (int o = 0; o < to; ++o) {
    const double a = o * step, b = (o + 1) * step;
    for (int i = int(std::floor(a)); i < std::min(from, int(std::ceil(b))); ++i) {
      const double overlap = std::min(b, i + 1.0) - std::max(a, double(i));
      if (overlap > 0) out[o].push_back({i, float(overlap / step)});
    }
  }
  return out;
}

}  // namespace

ImageF AreaResample(const ImageF& in, int width, int height) {
  if (width == in.width && height == in.height) return in;
  if (width < 1 || height < 1 || width > in.width || height > in.height)
    Fail("area resample: ", in.width, "x", in.height, " to ", width, "x", height, ": expected a smaller size");
  const auto wx = AreaWeights(in.width, width), wy = AreaWeights(in.height, height);
  ImageF rows(width, in.height, in.channels);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < width; ++x)
      for (auto [i, w] : wx[x])
        for (int c = 0; c < in.channels; ++c) rows.at(x, y, c) += w * in.at(i, y, c);
  ImageF out(width, height, in.channels);
  for (int y = 0; y < height; ++y)
    for (auto [j, w] : wy[y])
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < in.channels; ++c) out.at(x, y, c) += w * rows.at(x, j, c);
  return out;
}

Image8 AreaResampleRgba(const Image8& rgba, bool premultiplied, int width, int height) {
  if (rgba.channels != 4) Fail("area resample: expected RGBA, got ", rgba.channels, " channels");
  ImageF in(rgba.width, rgba.height, 4);
  for (int y = 0; y < rgba.height; ++y)
    for (int x = 0; x < rgba.width; ++x) {
      const float a = rgba.at(x, y, 3) / 255.0f;
      for (int c = 0; c < 3; ++c) in.at(x, y, c) = rgba.at(x, y, c) / 255.0f * (premultiplied ? 1.0f : a);
      in.at(x, y, 3) = a;
    }
  const ImageF small = AreaResample(in, width, height);
  Image8 out(width, height, 4);
  const auto byte = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float a = small.at(x, y, 3);
      for (int c = 0; c < 3; ++c)
        out.at(x, y, c) = byte(premultiplied ? small.at(x, y, c) : (a > 0 ? small.at(x, y, c) / a : 0.0f));
      out.at(x, y, 3) = byte(a);
    }
  return out;
}

}  // namespace voltree
