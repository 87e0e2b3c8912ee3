// The branches of a tree mesh as a graph of line segments, recovered from the bark triangles alone
// (an imported mesh has no skeleton): in each connected piece of bark, the vertices are banded by
// their distance along the surface from the piece's root, each band's connected parts become
// nodes at their centroids (a ring of a tube is one node), and each node hangs from the node of the
// band below it that it shares most edges with. Pieces hang from the nearest node of the pieces
// below them, so the graph is one tree.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lod/primitive_renderer.h"
#include "samples/tree_mesh.h"

namespace voltree {

struct SkeletonNode {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  int parent = -1;                                   // -1: the root
  float width = 0;                                   // of the segment to the parent (a branch diameter)
  Eigen::Vector3f colour = Eigen::Vector3f::Ones();  // of that segment, linear RGB
};

// Nodes come after their parents; one root when there is any bark.
struct BranchSkeleton {
  std::vector<SkeletonNode> nodes;
  size_t SegmentCount() const { return nodes.empty() ? 0 : nodes.size() - 1; }
};

struct BranchSkeletonOptions {
  // The band along the surface, in the mesh's units; 0: twice the median bark edge.
  double band = 0;
  void Check() const;  // throws OptionError for a negative band
};

// Empty when the mesh has no bark (only leaf materials).
BranchSkeleton ExtractBranchSkeleton(const TreeMesh& mesh, const BranchSkeletonOptions& options = {});

// One line per node with a parent.
std::vector<LinePrimitive> SkeletonLines(const BranchSkeleton& skeleton);

// Whether every node reaches the root through its parents (and there is exactly one root).
bool IsConnectedTree(const BranchSkeleton& skeleton);

}  // namespace voltree
