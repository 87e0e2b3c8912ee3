#include "render/orbit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"

namespace voltree {

void OrbitOptions::Check() const {
  if (frames < 1) Fail("orbit: frames must be >= 1, got ", frames);
  if (width < 1 || height < 1) Fail("orbit: size must be positive, got ", width, "x", height);
  if (!(margin >= 1)) Fail("orbit: margin must be >= 1, got ", margin);
}

std::vector<View> OrbitCameras(const VtreeAsset& asset, const OrbitOptions& options) {
  options.Check();
  if (asset.views.empty()) Fail("orbit: the asset has no input views to take distance and elevation from");
  const Eigen::Vector3d centre = 0.5 * (asset.bounds_min + asset.bounds_max);
  const double radius = std::max(0.5 * (asset.bounds_max - asset.bounds_min).norm(), 1e-6);
  double distance = 0, elevation = 0;
  for (const VtreeView& view : asset.views) {
    const Eigen::Vector3d d = view.position - centre;
    distance += d.norm();
    elevation += std::asin(std::clamp(d.z() / std::max(d.norm(), 1e-12), -1.0, 1.0));
  }
  distance /= double(asset.views.size());
  elevation /= double(asset.views.size());
  distance = std::max(distance, radius * options.margin * 1.01);  // stay outside the tree
  const Eigen::Vector3d first = asset.views[0].position - centre;
  constexpr double kDegrees = 180 / std::numbers::pi;
  return OrbitCamerasAround(centre, radius, distance, elevation * kDegrees, std::atan2(first.y(), first.x()) * kDegrees,
                            options);
}

std::vector<View> OrbitCamerasAround(const Eigen::Vector3d& centre, double radius, double distance,
                                     double elevation_degrees, double azimuth_degrees, const OrbitOptions& options) {
  options.Check();
  if (!(radius > 0) || !(distance > 0)) Fail("orbit: radius and distance must be > 0, got ", radius, " and ", distance);
  const double elevation = elevation_degrees * std::numbers::pi / 180,
               azimuth0 = azimuth_degrees * std::numbers::pi / 180;
  // Half field of view that holds the bounding sphere, with the margin.
  const double half_fov = std::min(std::asin(std::min(radius * options.margin / distance, 0.999)), 1.5);
  const double focal = 0.5 * std::min(options.width, options.height) / std::tan(half_fov);
  std::vector<View> views;
  for (int i = 0; i < options.frames; ++i) {
    const double azimuth = azimuth0 + 2 * std::numbers::pi * i / options.frames;
    const Eigen::Vector3d eye =
        centre + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                            std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    View view;
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%03d.png", i);
    view.name = name;
    view.camera =
        Camera::Pinhole(options.width, options.height, focal, focal, 0.5 * options.width, 0.5 * options.height);
    view.pose = Pose::LookAt(eye, centre, Eigen::Vector3d::UnitZ());
    views.push_back(view);
  }
  return views;
}

}  // namespace voltree
