// Builds the mesh a pruning method draws: every non-leaf triangle, plus the chosen leaves, each
// scaled about its own centre. Only the vertices drawn are kept, so the GPU cost is that of the
// simplified model.
#pragma once

#include <cstdint>
#include <vector>

#include "lod/leaf_separation.h"
#include "samples/tree_mesh.h"

namespace voltree {

struct LeafDraw {
  uint32_t leaf = 0;        // index into the leaves
  double area_scale = 1.0;  // the leaf's area is multiplied by this (lengths by its square root)
};

// `draws` may come in any order; leaves are emitted in mesh order so that the same set draws the
// same image. Throws Error for a leaf index out of range or a scale that is not positive.
TreeMesh BuildPrunedMesh(const TreeMesh& mesh, const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws);

// The total area of the drawn leaves after scaling.
double DrawnLeafArea(const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws);

}  // namespace voltree
