#include "render/frustum.h"

#include <algorithm>

namespace voltree {

Frustum::Frustum(const View& view) : pose_(view.pose) {
  view.camera.Check();
  // Tangents (x/z, y/z) of the image border: sampled along the edges so that barrel or pincushion
  // distortion cannot push the border outside the planes.
  const double w = view.camera.width, h = view.camera.height;
  double left = 0, right = 0, top = 0, bottom = 0;
  bool first = true;
  constexpr int kSamples = 16;
  for (int i = 0; i <= kSamples; ++i) {
    const double u = w * i / kSamples, v = h * i / kSamples;
    for (const Eigen::Vector2d& pixel :
         {Eigen::Vector2d(u, 0), Eigen::Vector2d(u, h), Eigen::Vector2d(0, v), Eigen::Vector2d(w, v)}) {
      const Eigen::Vector3d ray = view.camera.Unproject(pixel);  // z = 1
      if (first) left = right = ray.x(), top = bottom = ray.y(), first = false;
      left = std::min(left, ray.x()), right = std::max(right, ray.x());
      top = std::min(top, ray.y()), bottom = std::max(bottom, ray.y());
    }
  }
  // x >= left * z  <=>  (1, 0, -left) . p >= 0, and so on.
  normals_ = {Eigen::Vector3d(1, 0, -left).normalized(), Eigen::Vector3d(-1, 0, right).normalized(),
              Eigen::Vector3d(0, 1, -top).normalized(), Eigen::Vector3d(0, -1, bottom).normalized(),
              Eigen::Vector3d(0, 0, 1)};
}

bool Frustum::MayIntersect(const Sphere& sphere) const {
  const Eigen::Vector3d p = pose_.ToCamera(sphere.centre);
  for (const Eigen::Vector3d& n : normals_)
    if (n.dot(p) < -sphere.radius) return false;
  return true;
}

}  // namespace voltree
