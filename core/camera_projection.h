// COLMAP's camera models as templates over the scalar type, so that an optimiser can
// differentiate them (Ceres' Jets: capture/bundle_adjust.cpp). Camera::Distort and
// Camera::Project are these functions at double precision.
#pragma once

#include <Eigen/Core>

#include "core/camera.h"

namespace voltree {

// SIMPLE_PINHOLE, SIMPLE_RADIAL and RADIAL share one focal length: params f cx cy ...; the others
// have two: fx fy cx cy ...
constexpr bool HasSingleFocal(CameraModel model) {
  return model == CameraModel::kSimplePinhole || model == CameraModel::kSimpleRadial || model == CameraModel::kRadial;
}

// Normalized image coordinates (x/z, y/z) -> distorted normalized coordinates; `params` in
// COLMAP's order for `model`.
template <typename T>
Eigen::Matrix<T, 2, 1> DistortNormalized(CameraModel model, const T* params, const Eigen::Matrix<T, 2, 1>& n) {
  const T u = n.x(), v = n.y();
  const T r2 = u * u + v * v;
  switch (model) {
    case CameraModel::kSimplePinhole:
    case CameraModel::kPinhole:
      return n;
    case CameraModel::kSimpleRadial:
      return n * (T(1) + params[3] * r2);
    case CameraModel::kRadial:
      return n * (T(1) + params[3] * r2 + params[4] * r2 * r2);
    case CameraModel::kOpenCV: {
      const T &k1 = params[4], &k2 = params[5], &p1 = params[6], &p2 = params[7];
      const T radial = T(1) + k1 * r2 + k2 * r2 * r2;
      const T uv = u * v;
      return {u * radial + T(2) * p1 * uv + p2 * (r2 + T(2) * u * u),
              v * radial + T(2) * p2 * uv + p1 * (r2 + T(2) * v * v)};
    }
  }
  return n;
}

// Camera-space point (z > 0) -> pixel coordinates, distortion applied.
template <typename T>
Eigen::Matrix<T, 2, 1> ProjectToPixel(CameraModel model, const T* params, const Eigen::Matrix<T, 3, 1>& point) {
  const Eigen::Matrix<T, 2, 1> distorted =
      DistortNormalized(model, params, Eigen::Matrix<T, 2, 1>(point.x() / point.z(), point.y() / point.z()));
  const bool single = HasSingleFocal(model);
  const T& fx = params[0];
  const T& fy = single ? params[0] : params[1];
  const T& cx = single ? params[1] : params[2];
  const T& cy = single ? params[2] : params[3];
  return {fx * distorted.x() + cx, fy * distorted.y() + cy};
}

}  // namespace voltree
