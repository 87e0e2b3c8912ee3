// Analytic mattes of a box for the calibration and normalization tests.
#pragma once

#include <algorithm>
#include <utility>

#include "core/camera.h"
#include "core/image.h"

namespace voltree::test {

// 255 where the pixel's ray hits the box [-0.2, 0.2]^2 x [0, 1], else 0 (slab test).
inline Image8 BoxMatte(const View& view) {
  Image8 matte(view.camera.width, view.camera.height, 1);
  const Eigen::Vector3d low(-0.2, -0.2, 0), high(0.2, 0.2, 1), origin = view.pose.Center();
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) {
      const Eigen::Vector3d d = view.PixelRay({x + 0.5, y + 0.5});
      double near = 0, far = 1e9;
      for (int k = 0; k < 3; ++k) {
        double a = (low[k] - origin[k]) / d[k], b = (high[k] - origin[k]) / d[k];
        if (a > b) std::swap(a, b);
        near = std::max(near, a);
        far = std::min(far, b);
      }
      matte.at(x, y) = near <= far ? 255 : 0;
    }
  return matte;
}

}  // namespace voltree::test
