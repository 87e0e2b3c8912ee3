// Where an instance of an asset stands in a scene: a similarity from the asset's own frame (+Z
// up, origin at the base of the trunk) to the world, world = translation + scale * Rz(angle) * p.
// Rotation is about +Z only, so the tree stays upright and the ground stays the ground.
#pragma once

#include <Eigen/Core>

namespace voltree {

struct InstanceTransform {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double rotation_degrees = 0;  // about +Z, counter-clockwise seen from above
  double scale = 1;             // uniform, > 0
  void Check() const;

  Eigen::Matrix3d Rotation() const;  // Rz(rotation_degrees)
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& asset_point) const;
  Eigen::Vector3d ToAsset(const Eigen::Vector3d& world_point) const;
  // Directions ignore translation and scale (they stay unit vectors).
  Eigen::Vector3d DirectionToWorld(const Eigen::Vector3d& asset_direction) const;
  Eigen::Vector3d DirectionToAsset(const Eigen::Vector3d& world_direction) const;
  bool IsIdentity() const { return translation.isZero(0) && rotation_degrees == 0 && scale == 1; }
};

}  // namespace voltree
