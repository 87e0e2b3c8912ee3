#include "render/instance_transform.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace voltree {

void InstanceTransform::Check() const {
  if (!(scale > 0) || !std::isfinite(scale)) Fail("instance: scale must be a finite number > 0, got ", scale);
  if (!std::isfinite(rotation_degrees)) Fail("instance: rotation must be finite, got ", rotation_degrees);
  if (!translation.allFinite()) Fail("instance: position must be finite");
}

Eigen::Matrix3d InstanceTransform::Rotation() const {
  return Eigen::AngleAxisd(rotation_degrees * std::numbers::pi / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

Eigen::Vector3d InstanceTransform::ToWorld(const Eigen::Vector3d& p) const {
  return translation + scale * (Rotation() * p);
}

Eigen::Vector3d InstanceTransform::ToAsset(const Eigen::Vector3d& p) const {
  return Rotation().transpose() * (p - translation) / scale;
}

Eigen::Vector3d InstanceTransform::DirectionToWorld(const Eigen::Vector3d& d) const { return Rotation() * d; }
Eigen::Vector3d InstanceTransform::DirectionToAsset(const Eigen::Vector3d& d) const {
  return Rotation().transpose() * d;
}

}  // namespace voltree
