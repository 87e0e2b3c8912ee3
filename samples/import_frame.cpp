#include "samples/import_frame.h"

#include <algorithm>
#include <limits>

namespace voltree {

Eigen::Matrix3f UpToZRotation(UpAxis up) {
  Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();
  if (up == UpAxis::kY)
    rotation << 1, 0, 0,  //
        0, 0, -1,         //
        0, 1, 0;          // +90 degrees about X
  return rotation;
}

Eigen::Vector3f TrunkBase(const std::vector<MeshVertex>& vertices) {
  if (vertices.empty()) return Eigen::Vector3f::Zero();
  float z_min = std::numeric_limits<float>::max(), z_max = -z_min;
  for (const MeshVertex& v : vertices) {
    z_min = std::min(z_min, v.position.z());
    z_max = std::max(z_max, v.position.z());
  }
  const float slab_top = z_min + kTrunkBaseSlab * (z_max - z_min);
  Eigen::Vector2f lo = Eigen::Vector2f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  for (const MeshVertex& v : vertices) {
    if (v.position.z() > slab_top) continue;
    lo = lo.cwiseMin(v.position.head<2>());
    hi = hi.cwiseMax(v.position.head<2>());
  }
  const Eigen::Vector2f centre = 0.5f * (lo + hi);
  return {centre.x(), centre.y(), z_min};
}

void MoveToTreeFrame(UpAxis up, TreeMesh* mesh) {
  const Eigen::Matrix3f rotation = UpToZRotation(up);
  for (MeshVertex& v : mesh->vertices) {
    v.position = rotation * v.position;
    v.normal = rotation * v.normal;
  }
  const Eigen::Vector3f base = TrunkBase(mesh->vertices);
  for (MeshVertex& v : mesh->vertices) v.position -= base;
}

}  // namespace voltree
