// The studio's light: a sun (directional) and a sky dome, in linear RGB.
#pragma once

#include <Eigen/Core>

#include "samples/studio_options.h"

namespace voltree {

struct StudioLighting {
  Eigen::Vector3f sun_direction = Eigen::Vector3f::UnitZ();  // unit, towards the sun
  Eigen::Vector3f sun_color{2.4f, 2.25f, 2.0f};
  Eigen::Vector3f sky_zenith{0.16f, 0.32f, 0.75f};      // sky colour straight up
  Eigen::Vector3f sky_horizon{0.62f, 0.72f, 0.85f};     // and at the horizon
  Eigen::Vector3f sky_ambient{0.30f, 0.36f, 0.46f};     // irradiance from the sky on an upward surface
  Eigen::Vector3f ground_ambient{0.10f, 0.10f, 0.07f};  // light bounced from the ground
};

StudioLighting MakeStudioLighting(const StudioOptions& options);

}  // namespace voltree
