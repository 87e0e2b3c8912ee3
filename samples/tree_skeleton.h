// The branching skeleton of a procedural tree: polylines with radii, grown from a TreeShape.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "samples/tree_random.h"
#include "samples/tree_shape.h"

namespace voltree {

struct BranchNode {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  float radius = 0.0f;
};

struct Branch {
  int level = 0;
  int parent = -1;                // index into Skeleton::branches, -1 for the trunk
  std::vector<BranchNode> nodes;  // base to tip, at least two
  float Length() const;
};

struct Skeleton {
  std::vector<Branch> branches;  // parents before children
};

// A point on a branch: position, unit direction of travel and radius.
struct BranchFrame {
  Eigen::Vector3f position;
  Eigen::Vector3f direction;
  float radius;
};

// The frame at arc-length fraction t in [0, 1] of a branch.
BranchFrame SampleBranch(const Branch& branch, float t);

// Grows the trunk and every branch level. Deterministic in `random`.
Skeleton GrowSkeleton(const TreeShape& shape, TreeRandom& random);

// Any unit vector perpendicular to `direction` (stable: same input, same output).
Eigen::Vector3f AnyPerpendicular(const Eigen::Vector3f& direction);

}  // namespace voltree
