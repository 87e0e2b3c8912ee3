#include "render/lod.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

LodRule LodRuleFromName(const std::string& name) {
  if (name == "screen") return LodRule::kScreen;
  if (name == "planes") return LodRule::kPlanes;
  Fail("lod: unknown rule '", name, "' (expected screen or planes)");
}

const char* LodRuleName(LodRule rule) { return rule == LodRule::kPlanes ? "planes" : "screen"; }

void LodOptions::Check() const {
  if (rule != LodRule::kScreen && rule != LodRule::kPlanes) Fail("lod: unknown rule ", int(rule));
  if (forced_level < -1)
    FailOption("LodOptions.forced_level", "must be >= 0 (or -1 for automatic), got ", forced_level);
  if (!(max_texel_pixels > 0)) FailOption("LodOptions.max_texel_pixels", "must be > 0, got ", max_texel_pixels);
  if (!(hysteresis >= 0 && hysteresis < 1)) FailOption("LodOptions.hysteresis", "must be in [0, 1), got ", hysteresis);
}

double TexelPixels(double cell_size, int texels, double distance, double focal_pixels) {
  return focal_pixels * (cell_size / std::max(texels, 1)) / std::max(distance, 1e-9);
}

double LodPlaneDepth(const LodOptions& options, double cell_size, int texels, double focal_pixels) {
  return focal_pixels * (cell_size / std::max(texels, 1)) / options.max_texel_pixels;
}

bool ShouldDescend(const LodOptions& options, int level, int finest_level, double cell_size, int texels,
                   double distance, double half_diagonal, double focal_pixels, int previous) {
  if (level >= finest_level) return false;
  if (options.forced_level >= 0) return level < options.forced_level;
  if (distance < -half_diagonal) return false;  // wholly behind the camera plane (kPlanes only)
  if (distance <= half_diagonal) return true;   // the eye is inside, or the cell straddles the plane
  const double band = previous < 0 ? 1.0 : previous ? 1.0 - options.hysteresis : 1.0 + options.hysteresis;
  return TexelPixels(cell_size, texels, distance, focal_pixels) > options.max_texel_pixels * band;
}

}  // namespace voltree
