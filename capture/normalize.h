// Scene normalization: bring a COLMAP reconstruction (arbitrary frame and scale) into the tree
// frame: +Z up, origin at the base of the trunk, metres when the tree's height is known.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/camera.h"
#include "core/colmap_model.h"

namespace voltree {

// x' = scale * rotation * x + translation.
struct Similarity {
  double scale = 1.0;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& x) const { return scale * (rotation * x) + translation; }
  // Applies `this` after `first`.
  Similarity After(const Similarity& first) const;
};

// The same scene seen in the new frame: camera poses, and points moved.
Pose TransformPose(const Pose& pose, const Similarity& similarity);
ColmapModel TransformModel(const ColmapModel& model, const Similarity& similarity);

// World up from cameras that circle the tree. The normal of the least-squares plane through the
// camera centres, when they are flat (an orbit) and the normal is within 30 degrees of the photos'
// up; otherwise (a line of cameras, fewer than 3) the mean of the cameras' image-up axes. The sign always follows the
// image-up axes: photos are taken upright, so the cameras' -Y axes, averaged, point up. Throws Error when there are no
// views.
Eigen::Vector3d EstimateUp(const std::vector<View>& views);

// The rotation taking `up` to +Z (the shortest arc; heading is left as it is).
Eigen::Quaterniond RotationToZUp(const Eigen::Vector3d& up);

// The point closest (least squares) to all optical axes: what the cameras look at.
Eigen::Vector3d LookAtPoint(const std::vector<View>& views);

// The height of the ground under a tree in a Z-up frame, from sparse points: the densest
// horizontal slab (thickness `slab`) among the points within `radius` of `center` horizontally
// and with z in [z_low, z_high]; the median z of that slab. Empty when fewer than `min_points`
// points fall in it. A visual hull reaches below the trunk base (the silhouette cones of the
// trunk meet under the ground), the textured ground around the tree does not.
std::optional<double> EstimateGroundHeight(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& center,
                                           double radius, double z_low, double z_high, double slab,
                                           int min_points = 20);

}  // namespace voltree
