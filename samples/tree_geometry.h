// Turns a grown skeleton into triangles: bark-textured tubes for the branches and alpha-textured
// quads for the foliage.
#pragma once

#include "samples/tree_mesh.h"
#include "samples/tree_random.h"
#include "samples/tree_shape.h"
#include "samples/tree_skeleton.h"

namespace voltree {

// Appends one tapered tube per branch (parallel-transported rings, so they do not twist), with
// root buttresses on the trunk. The bark texture repeats around and along each branch.
void AppendBranchTubes(const TreeShape& shape, const Skeleton& skeleton, TreeMesh& mesh, MeshGroup& group);

// Appends exactly shape.foliage.count quads, spread evenly over the leaf-bearing part of the
// outer branches, each showing one random cell of the foliage atlas. Returns the quad count.
size_t AppendFoliage(const TreeShape& shape, const Skeleton& skeleton, TreeRandom& random, TreeMesh& mesh,
                     MeshGroup& group);

}  // namespace voltree
