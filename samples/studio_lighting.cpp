#include "samples/studio_lighting.h"

#include <cmath>
#include <numbers>

namespace voltree {

StudioLighting MakeStudioLighting(const StudioOptions& options) {
  constexpr double kDegrees = std::numbers::pi / 180;
  const double azimuth = options.sun_azimuth_degrees * kDegrees, elevation = options.sun_elevation_degrees * kDegrees;
  StudioLighting lighting;
  lighting.sun_direction = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                           std::cos(elevation) * std::sin(azimuth), std::sin(elevation))
                               .cast<float>();
  return lighting;
}

float DecodeSrgb(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float EncodeSrgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

}  // namespace voltree
