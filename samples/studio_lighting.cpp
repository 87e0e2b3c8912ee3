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

}  // namespace voltree
