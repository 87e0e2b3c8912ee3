// Moving an imported mesh into the normalized tree frame: the file's up axis becomes +Z and the
// base of the trunk the origin; units are kept.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "samples/mesh_import.h"
#include "samples/tree_mesh.h"

namespace voltree {

// The proper rotation (det +1) taking `up` to +Z: for +Y, x stays, y -> z, z -> -y.
Eigen::Matrix3f UpToZRotation(UpAxis up);

// Fraction of the height, from the lowest vertex, whose vertices locate the trunk base.
inline constexpr float kTrunkBaseSlab = 0.02f;

// Centre in x,y of the bounding box of the vertices within the lowest kTrunkBaseSlab of the
// height, and the lowest z. Z-up positions expected. The box centre (not the mean) so a densely
// tessellated root on one side does not pull the origin off the trunk axis.
Eigen::Vector3f TrunkBase(const std::vector<MeshVertex>& vertices);

// Rotates positions and normals by UpToZRotation(up), then translates the trunk base to 0.
void MoveToTreeFrame(UpAxis up, TreeMesh* mesh);

}  // namespace voltree
