#include "samples/studio_rig.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"

namespace voltree {
namespace {

constexpr double kDegrees = std::numbers::pi / 180;

std::string ViewName(const char* prefix, int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%s_%03d.png", prefix, index);
  return name;
}

// A fraction in [0, 1) from the seed (splitmix64), so different seeds turn the rings.
double SeedFraction(uint64_t seed) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / static_cast<double>(1ull << 53);
}

Eigen::Vector3d Direction(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

View MakeView(const std::string& name, const Camera& camera, const Eigen::Vector3d& target, double distance,
              const Eigen::Vector3d& direction) {
  View view;
  view.name = name;
  view.camera = camera;
  view.pose = Pose::LookAt(target + distance * direction, target, Eigen::Vector3d::UnitZ());
  return view;
}

// Whether all corners of the bounds project inside the frame less its margin.
bool Frames(const View& view, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double margin) {
  const double mx = margin * view.camera.width / 2, my = margin * view.camera.height / 2;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    Eigen::Vector2d pixel;
    if (!view.WorldToPixel(p, &pixel) || view.pose.ToCamera(p).z() < 1e-6) return false;
    if (pixel.x() < mx || pixel.y() < my || pixel.x() > view.camera.width - mx || pixel.y() > view.camera.height - my)
      return false;
  }
  return true;
}

// The smallest distance along `direction` at which the bounds fit the frame (bisection; the
// bounding sphere's distance is the starting upper bound).
double FramingDistance(const Camera& camera, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const Eigen::Vector3d& target, const Eigen::Vector3d& direction, double sphere_distance,
                       double margin) {
  const auto fits = [&](double d) { return Frames(MakeView("", camera, target, d, direction), lo, hi, margin); };
  double far = sphere_distance;
  for (int i = 0; i < 20 && !fits(far); ++i) far *= 1.5;  // strong pincushion distortion
  double near = 0;
  for (int i = 0; i < 40; ++i) {
    const double middle = 0.5 * (near + far);
    (fits(middle) ? far : near) = middle;
  }
  return far;
}

}  // namespace

StudioRig MakeStudioRig(const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max,
                        const StudioOptions& options) {
  options.Check();
  if (!(bounds_min.array() <= bounds_max.array()).all() || !bounds_min.allFinite() || !bounds_max.allFinite())
    Fail("studio: the tree's bounds are empty or not finite");
  const Camera camera = MakeStudioCamera(options);
  StudioRig rig;
  rig.target = 0.5 * (bounds_min + bounds_max);
  // Fit the bounding sphere inside the cone of half-angle atan(tan(fov/2) * (1 - margin)).
  const double radius = std::max(0.5 * (bounds_max - bounds_min).norm(), 1e-3);
  const double half_angle = std::atan(std::tan(0.5 * options.fov_degrees * kDegrees) * (1 - options.margin));
  const double sphere_distance = radius / std::sin(half_angle);

  const double low = options.min_elevation_degrees * kDegrees, high = options.max_elevation_degrees * kDegrees;
  const auto ring_elevation = [&](double ring) {
    return options.rings == 1 ? 0.5 * (low + high) : low + (high - low) * ring / (options.rings - 1);
  };
  const double first_azimuth = 2 * std::numbers::pi * SeedFraction(options.seed);

  std::vector<std::pair<std::string, Eigen::Vector3d>> inputs, held_out;
  int index = 0;
  for (int ring = 0; ring < options.rings; ++ring) {
    const int count = options.views / options.rings + (ring < options.views % options.rings ? 1 : 0);
    const double stagger = static_cast<double>(ring) / options.rings;  // rings do not line up
    for (int k = 0; k < count; ++k, ++index) {
      const double azimuth = first_azimuth + 2 * std::numbers::pi * (k + stagger) / count;
      inputs.emplace_back(ViewName("view", index), Direction(azimuth, ring_elevation(ring)));
    }
  }
  for (int k = 0; k < options.held_out; ++k) {
    // Halfway between rings; with one ring, halfway between it and 15 degrees higher.
    const double elevation =
        options.rings == 1 ? ring_elevation(0) + 7.5 * kDegrees : ring_elevation((k % (options.rings - 1)) + 0.5);
    const double per_ring = static_cast<double>(options.views) / options.rings;
    const double azimuth =
        first_azimuth + 2 * std::numbers::pi * (k + 0.5) / options.held_out + std::numbers::pi / (2 * per_ring);
    held_out.emplace_back(ViewName("held", k), Direction(azimuth, elevation));
  }
  // One distance for all views, the largest any of them needs, so that every view frames the tree.
  for (const auto* list : {&inputs, &held_out})
    for (const auto& [name, direction] : *list)
      rig.distance = std::max(rig.distance, FramingDistance(camera, bounds_min, bounds_max, rig.target, direction,
                                                            sphere_distance, options.margin));
  for (const auto& [name, direction] : inputs)
    rig.inputs.push_back(MakeView(name, camera, rig.target, rig.distance, direction));
  for (const auto& [name, direction] : held_out)
    rig.held_out.push_back(MakeView(name, camera, rig.target, rig.distance, direction));
  return rig;
}

}  // namespace voltree
