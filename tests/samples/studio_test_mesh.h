// Small hand-built meshes for the studio tests: exact geometry, no dependence on the generator.
#pragma once

#include <Eigen/Core>

#include "samples/tree_mesh.h"

namespace voltree::testing {

// Appends an axis-aligned box as 12 triangles (normals per face) to group `group` of `mesh`.
inline void AddBox(TreeMesh& mesh, int group, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Eigen::Vector3f normal = Eigen::Vector3f::Zero();
      normal[axis] = side ? 1.0f : -1.0f;
      const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
      for (int corner = 0; corner < 4; ++corner) {
        Eigen::Vector3f p;
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = (corner & 1) ? hi[u] : lo[u];
        p[v] = (corner & 2) ? hi[v] : lo[v];
        MeshVertex vertex;
        vertex.position = p;
        vertex.normal = normal;
        vertex.uv = Eigen::Vector2f((corner & 1) ? 1.0f : 0.0f, (corner & 2) ? 4.0f : 0.0f);
        mesh.vertices.push_back(vertex);
      }
      for (uint32_t index : {0u, 1u, 3u, 0u, 3u, 2u}) mesh.groups[group].indices.push_back(first + index);
    }
}

// A tiny opaque white cube centred on `center`, alone in its mesh.
inline TreeMesh MakeCubeMesh(const Eigen::Vector3f& center, float half_size) {
  TreeMesh mesh;
  mesh.materials.push_back(Material{"white", Eigen::Vector4f::Ones(), -1, AlphaMode::kOpaque, 0.5f, false});
  mesh.groups.push_back(MeshGroup{0, {}});
  AddBox(mesh, 0, center - Eigen::Vector3f::Constant(half_size), center + Eigen::Vector3f::Constant(half_size));
  return mesh;
}

// A 2 m "tree": a textured trunk box and a few dozen double-sided, alpha-tested leaf cards (a
// disc in a 32x32 texture) around a crown at 1.5 m.
inline TreeMesh MakeToyTree() {
  TreeMesh mesh;
  Image8 bark(16, 16, 4);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const uint8_t shade = static_cast<uint8_t>(((x / 4 + y / 2) % 2) ? 120 : 70);
      bark.at(x, y, 0) = shade;
      bark.at(x, y, 1) = static_cast<uint8_t>(shade * 3 / 4);
      bark.at(x, y, 2) = static_cast<uint8_t>(shade / 2);
      bark.at(x, y, 3) = 255;
    }
  Image8 leaf(32, 32, 4);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const float dx = x + 0.5f - 16, dy = y + 0.5f - 16;
      leaf.at(x, y, 0) = 60;
      leaf.at(x, y, 1) = 140;
      leaf.at(x, y, 2) = 40;
      leaf.at(x, y, 3) = dx * dx + dy * dy < 14 * 14 ? 255 : 0;
    }
  mesh.textures = {bark, leaf};
  mesh.materials.push_back(Material{"bark", Eigen::Vector4f::Ones(), 0, AlphaMode::kOpaque, 0.5f, false});
  mesh.materials.push_back(Material{"leaf", Eigen::Vector4f::Ones(), 1, AlphaMode::kMask, 0.5f, true});
  mesh.groups.push_back(MeshGroup{0, {}});
  mesh.groups.push_back(MeshGroup{1, {}});
  AddBox(mesh, 0, Eigen::Vector3f(-0.06f, -0.06f, 0.0f), Eigen::Vector3f(0.06f, 0.06f, 1.6f));
  // Leaf cards on a deterministic spiral, tilted differently.
  for (int i = 0; i < 40; ++i) {
    const float angle = 2.39996f * i, radius = 0.15f + 0.55f * ((i * 37) % 40) / 40.0f;
    const Eigen::Vector3f center(radius * std::cos(angle), radius * std::sin(angle), 1.1f + 0.02f * i);
    const Eigen::Vector3f right = Eigen::Vector3f(-std::sin(angle), std::cos(angle), 0.0f) * 0.15f;
    const Eigen::Vector3f up =
        Eigen::Vector3f(0.3f * std::cos(angle), 0.3f * std::sin(angle), 1.0f).normalized() * (0.15f + 0.05f * (i % 3));
    const Eigen::Vector3f normal = right.cross(up).normalized();
    const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
    for (int corner = 0; corner < 4; ++corner) {
      MeshVertex vertex;
      const float su = (corner & 1) ? 1.0f : -1.0f, sv = (corner & 2) ? 1.0f : -1.0f;
      vertex.position = center + su * right + sv * up;
      vertex.normal = normal;
      vertex.uv = Eigen::Vector2f((corner & 1) ? 1.0f : 0.0f, (corner & 2) ? 0.0f : 1.0f);
      vertex.tint = Eigen::Vector3f(1.0f, 0.8f + 0.01f * (i % 20), 1.0f);
      mesh.vertices.push_back(vertex);
    }
    for (uint32_t index : {0u, 1u, 3u, 0u, 3u, 2u}) mesh.groups[1].indices.push_back(first + index);
  }
  return mesh;
}

}  // namespace voltree::testing
