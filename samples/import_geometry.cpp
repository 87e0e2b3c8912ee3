#include "samples/import_geometry.h"

#include <Eigen/Geometry>

#include <cmath>

namespace voltree {

std::vector<Eigen::Vector3f> AreaWeightedNormals(const std::vector<MeshVertex>& vertices,
                                                 const std::vector<uint32_t>& triangles) {
  std::vector<Eigen::Vector3f> sums(vertices.size(), Eigen::Vector3f::Zero());
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    // The cross product's length is twice the area: larger faces weigh more.
    const Eigen::Vector3f face =
        (vertices[b].position - vertices[a].position).cross(vertices[c].position - vertices[a].position);
    sums[a] += face;
    sums[b] += face;
    sums[c] += face;
  }
  for (Eigen::Vector3f& n : sums) {
    const float length = n.norm();
    n = length > 0 && std::isfinite(length) ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
  }
  return sums;
}

void RemoveUnusedVertices(TreeMesh* mesh) {
  constexpr uint32_t kUnused = ~uint32_t{0};
  std::vector<uint32_t> remap(mesh->vertices.size(), kUnused);
  for (const MeshGroup& group : mesh->groups)
    for (uint32_t index : group.indices) remap[index] = 0;
  std::vector<MeshVertex> kept;
  for (size_t i = 0; i < mesh->vertices.size(); ++i) {
    if (remap[i] == kUnused) continue;
    remap[i] = static_cast<uint32_t>(kept.size());
    kept.push_back(mesh->vertices[i]);
  }
  if (kept.size() == mesh->vertices.size()) return;
  for (MeshGroup& group : mesh->groups)
    for (uint32_t& index : group.indices) index = remap[index];
  mesh->vertices = std::move(kept);
}

}  // namespace voltree
