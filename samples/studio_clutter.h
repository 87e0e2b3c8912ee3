// What stands on the ground of the studio's realistic backdrop: bushes, rocks and other trees,
// scattered around the tree outside the camera ring (so that none stands between a camera and
// the tree: the photo puts the tree over the backdrop whatever their depths). Deterministic from
// the seed.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace voltree {

struct ClutterObject {
  enum Kind { kBush = 0, kRock = 1, kTree = 2 };
  Kind kind = kBush;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // of the ellipsoid (a tree's crown)
  double radius = 1;                                 // horizontal
  double vertical_radius = 1;
  double trunk_radius = 0;  // trees: the trunk runs from 0 to centre.z()
  double tint = 0;          // 0..1, varies the colour
};

struct ClutterLayout {
  std::vector<ClutterObject> objects;
  double wall_radius = 0;  // the skyline's distance from the tree
};

// `centre`: the tree on the ground; `tree_height` scales the objects; `clear_radius`: nothing
// nearer to the centre (the camera ring's horizontal radius plus a margin).
ClutterLayout MakeStudioClutter(uint64_t seed, const Eigen::Vector2d& centre, double tree_height, double clear_radius);

}  // namespace voltree
