#include "samples/tree_mesh.h"

#include <limits>

#include "core/error.h"

namespace voltree {

float AlphaCutoff(const Material& material) {
  switch (material.alpha_mode) {
    case AlphaMode::kOpaque:
      return -1.0f;
    case AlphaMode::kMask:
      return material.alpha_cutoff;
    case AlphaMode::kBlend:
      return 0.5f;
  }
  return -1.0f;
}

size_t TreeMesh::TriangleCount() const {
  size_t count = 0;
  for (const MeshGroup& group : groups) count += group.indices.size() / 3;
  return count;
}

std::pair<Eigen::Vector3f, Eigen::Vector3f> TreeMesh::Bounds() const {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  for (const MeshVertex& v : vertices) {
    lo = lo.cwiseMin(v.position);
    hi = hi.cwiseMax(v.position);
  }
  return {lo, hi};
}

std::pair<Eigen::Vector3f, Eigen::Vector3f> TreeMesh::CrownBounds() const {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e30f), hi = -lo;
  for (const MeshGroup& group : groups)
    if (materials[group.material].alpha_mode != AlphaMode::kOpaque)
      for (uint32_t index : group.indices) {
        lo = lo.cwiseMin(vertices[index].position);
        hi = hi.cwiseMax(vertices[index].position);
      }
  if (!(lo.array() <= hi.array()).all()) return Bounds();
  return {lo, hi};
}

void TreeMesh::Check() const {
  if (vertices.empty() || TriangleCount() == 0) Fail("the mesh has no triangles");
  for (size_t v = 0; v < vertices.size(); ++v)
    if (!vertices[v].position.allFinite() || !vertices[v].normal.allFinite() || !vertices[v].uv.allFinite())
      Fail("mesh vertex ", v, " has a coordinate that is not a finite number (position ",
           vertices[v].position.transpose(), "); expected finite positions, normals and texture coordinates");
  for (size_t g = 0; g < groups.size(); ++g) {
    const MeshGroup& group = groups[g];
    if (group.indices.size() % 3 != 0) Fail("mesh group ", g, " has an index count not divisible by 3");
    if (group.material < 0 || group.material >= static_cast<int>(materials.size()))
      Fail("mesh group ", g, " refers to material ", group.material, " of ", materials.size());
    for (uint32_t index : group.indices)
      if (index >= vertices.size()) Fail("mesh group ", g, " refers to vertex ", index, " of ", vertices.size());
  }
  for (const Material& material : materials)
    if (material.texture >= static_cast<int>(textures.size()) ||
        (material.texture >= 0 && textures[material.texture].empty()))
      Fail("material '", material.name, "' refers to a missing texture ", material.texture);
}

}  // namespace voltree
