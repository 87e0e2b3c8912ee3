// View-frustum culling of bounding spheres, for scenes of many instances.
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/camera.h"

namespace voltree {

struct Sphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

// The pyramid of a camera's image in camera space: four side planes through the eye and the
// camera plane z = 0 (no far plane: scenes are small enough to draw to the horizon). The side
// planes bound the undistorted directions of the image border, so a distorted camera's frustum
// holds all it can see.
class Frustum {
 public:
  explicit Frustum(const View& view);
  // False only when the sphere is certainly outside (conservative near the pyramid's edges).
  bool MayIntersect(const Sphere& world_sphere) const;

 private:
  Pose pose_;
  std::array<Eigen::Vector3d, 5> normals_;  // unit, camera space, pointing inside
};

}  // namespace voltree
