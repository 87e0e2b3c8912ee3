#include "compress/synthetic_volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "compress/colour_space.h"
#include "core/error.h"

namespace voltree {
namespace {

double Uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }
double Range(std::mt19937_64& rng, double low, double high) { return low + (high - low) * Uniform(rng); }

// A base colour in Lab drawn from a foliage palette.
Lab FoliageColour(std::mt19937_64& rng) {
  const double pick = Uniform(rng);
  if (pick < 0.55)
    return {float(Range(rng, 25, 55)), float(Range(rng, -35, -10)), float(Range(rng, 15, 45))};                // leaves
  if (pick < 0.75) return {float(Range(rng, 45, 75)), float(Range(rng, -25, -5)), float(Range(rng, 35, 65))};  // sunlit
  if (pick < 0.90) return {float(Range(rng, 20, 45)), float(Range(rng, 5, 20)), float(Range(rng, 10, 30))};    // bark
  if (pick < 0.97) return {float(Range(rng, 3, 15)), float(Range(rng, -10, 0)), float(Range(rng, 0, 10))};     // shadow
  return {float(Range(rng, 80, 95)), float(Range(rng, -5, 5)), float(Range(rng, -15, 5))};  // sky gaps
}

void FillBillboard(std::mt19937_64& rng, int n, uint8_t* rgba) {
  const Lab base = FoliageColour(rng);
  // Smooth variation: a linear gradient in L*, a*, b* plus a little per-texel noise.
  const double gx = Range(rng, -12, 12), gy = Range(rng, -12, 12), ga = Range(rng, -6, 6), gb = Range(rng, -6, 6);
  const double cx = Range(rng, 0, n), cy = Range(rng, 0, n), radius = Range(rng, 0.6, 1.2) * n;
  const double peak = Range(rng, 0.35, 1.0);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double u = (x + 0.5) / n - 0.5, v = (y + 0.5) / n - 0.5;
      const Lab lab = {float(std::clamp(base[0] + gx * u + gy * v + Range(rng, -2, 2), 0.0, 100.0)),
                       float(base[1] + ga * u + Range(rng, -1.5, 1.5)),
                       float(base[2] + gb * v + Range(rng, -1.5, 1.5))};
      const auto rgb = LabToSrgb8(lab);
      const double distance = std::hypot(x + 0.5 - cx, y + 0.5 - cy) / radius;
      const double a = std::clamp(peak * (1.4 - distance) / 0.6, 0.0, peak);  // soft-edged blob
      const uint8_t alpha = static_cast<uint8_t>(std::lround(255 * a));
      uint8_t* out = rgba + 4 * (y * n + x);
      for (int c = 0; c < 3; ++c) out[c] = static_cast<uint8_t>((rgb[c] * alpha + 127) / 255);  // premultiplied
      out[3] = alpha;
    }
  }
  // At least one visible texel, as pruning guarantees for real volumes.
  bool visible = false;
  for (int t = 0; t < n * n; ++t) visible |= rgba[4 * t + 3] > 0;
  if (!visible) {
    const auto rgb = LabToSrgb8(base);
    std::copy(rgb.begin(), rgb.end(), rgba);
    rgba[3] = 255;
  }
}

}  // namespace

Volume MakeSyntheticVolume(const SyntheticVolumeOptions& options) {
  if (options.levels < 1 || options.levels > 10 || options.views < 1 || options.billboards < 1 || options.texels < 1)
    Fail("synthetic volume: invalid options");
  std::mt19937_64 rng(options.seed);
  Volume volume;
  volume.origin = Eigen::Vector3d(-1, -1, 0);
  volume.size = 2;
  volume.texels = options.texels;
  for (int v = 0; v < options.views; ++v) {
    const double angle = 2 * M_PI * v / options.views;
    VolumeView view;
    view.name = "view_" + std::to_string(v) + ".png";
    view.position = Eigen::Vector3d(4 * std::cos(angle), 4 * std::sin(angle), 1);
    view.direction = (Eigen::Vector3d(0, 0, 1) - view.position).normalized();
    view.up = Eigen::Vector3d::UnitZ();
    volume.views.push_back(view);
  }
  // Billboards per level grow with the level like an octree's do: weights 1, 2, 4, ...
  const double weight_sum = std::pow(2.0, options.levels) - 1;
  const size_t texel_bytes = size_t(options.texels) * options.texels * 4;
  for (int l = 0; l < options.levels; ++l) {
    VolumeLevel level;
    level.resolution = 1 << l;
    const int wanted = std::max(1, int(std::lround(options.billboards * std::pow(2.0, l) / weight_sum)));
    const int cell_limit = level.resolution * level.resolution * level.resolution;
    const int cells = std::min(cell_limit, std::max(1, (wanted + options.views - 1) / options.views));
    for (int c = 0; c < cells; ++c) {
      const int index = int(uint64_t(c) * 2654435761u % uint64_t(cell_limit));  // spread over the grid
      const int r = level.resolution;
      level.cells.push_back({uint16_t(index % r), uint16_t(index / r % r), uint16_t(index / (r * r))});
      level.density.push_back(float(Range(rng, 0.1, 5)));
    }
    // Sorted by (z, y, x), as the volume's contract asks (core/volume.h).
    const auto zyx = [](const std::array<uint16_t, 3>& c) { return std::array{c[2], c[1], c[0]}; };
    std::sort(level.cells.begin(), level.cells.end(), [&](const auto& a, const auto& b) { return zyx(a) < zyx(b); });
    level.cells.erase(std::unique(level.cells.begin(), level.cells.end()), level.cells.end());
    level.density.resize(level.cells.size());
    for (uint32_t c = 0; c < level.cells.size() && int(level.billboards.size()) < wanted; ++c)
      for (int v = 0; v < options.views && int(level.billboards.size()) < wanted; ++v)
        level.billboards.push_back({c, uint16_t(v)});
    level.billboards_before_pruning = level.cells.size() * options.views;
    level.texels.resize(level.billboards.size() * texel_bytes);
    for (size_t b = 0; b < level.billboards.size(); ++b)
      FillBillboard(rng, options.texels, level.texels.data() + b * texel_bytes);
    volume.levels.push_back(std::move(level));
  }
  return volume;
}

}  // namespace voltree
