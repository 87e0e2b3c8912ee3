// Geometry clean-up shared by the importers: normals for files that lack them, and dropping
// vertices no triangle uses (glTF accessors may hold more than a primitive draws).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

// Area-weighted vertex normals of `triangles` (three indices each, into `vertices`); a vertex
// on no triangle or only on degenerate ones gets +Z. Serial, so the result is deterministic.
std::vector<Eigen::Vector3f> AreaWeightedNormals(const std::vector<MeshVertex>& vertices,
                                                 const std::vector<uint32_t>& triangles);

// Removes vertices that no group refers to, keeping the order of the others.
void RemoveUnusedVertices(TreeMesh* mesh);

}  // namespace voltree
