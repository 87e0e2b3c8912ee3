// Splits a tree mesh's foliage into leaves, the unit that pruning removes and scales: each leaf is
// a connected set of triangles of a leaf material (alpha-tested or blended, or named "leaves"),
// connected through shared vertex indices or identical vertex positions (unwelded quads).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

struct Leaf {
  int group = 0;                                     // index into TreeMesh::groups
  std::vector<uint32_t> triangles;                   // triangle numbers within that group, ascending
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();  // area-weighted centroid, what scaling keeps fixed
  double area = 0;                                   // one-sided
};

// Whether a material is foliage: alpha-tested or blended (leaf cards), or named like the
// procedural generator's leaves.
bool IsLeafMaterial(const Material& material);

// All leaves, ordered by group, then by their first triangle. Empty when the mesh has no leaf
// material (a mesh without separable leaves).
std::vector<Leaf> SeparateLeaves(const TreeMesh& mesh);

double TotalLeafArea(const std::vector<Leaf>& leaves);

}  // namespace voltree
