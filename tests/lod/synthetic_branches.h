// A small branching tree of bark tubes, as the procedural generator makes them: one hexagonal tube
// per branch (rings every `step`), each a separate piece of mesh starting inside its parent, Z up;
// optionally with leaf cards at the branch tips.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "samples/tree_mesh.h"

namespace voltree::test {

inline void AppendTube(TreeMesh& mesh, MeshGroup& group, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                       float radius, float step = 0.05f) {
  const Eigen::Vector3f axis = (b - a).normalized();
  const Eigen::Vector3f side = axis.unitOrthogonal(), up = axis.cross(side);
  const int rings = std::max(2, static_cast<int>(std::ceil((b - a).norm() / step)) + 1);
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < 6; ++s) {
      const float angle = 2 * std::numbers::pi_v<float> * s / 6;
      MeshVertex v;
      v.normal = std::cos(angle) * side + std::sin(angle) * up;
      v.position = a + (b - a) * (static_cast<float>(r) / (rings - 1)) + radius * v.normal;
      mesh.vertices.push_back(v);
    }
  for (int r = 0; r + 1 < rings; ++r)
    for (uint32_t s = 0; s < 6; ++s) {
      const uint32_t i = base + 6 * r + s, j = base + 6 * r + (s + 1) % 6;
      group.indices.insert(group.indices.end(), {i, j, j + 6, i, j + 6, i + 6});
    }
}

// A trunk, two branches and a twig; `leaves`: a square card at each branch tip.
inline TreeMesh SyntheticBranches(bool leaves = false) {
  TreeMesh mesh;
  mesh.materials.push_back(Material{.name = "bark"});
  MeshGroup bark{0, {}};
  AppendTube(mesh, bark, {0, 0, 0}, {0, 0, 1}, 0.05f);
  AppendTube(mesh, bark, {0, 0, 0.6f}, {0.4f, 0, 1.0f}, 0.02f);
  AppendTube(mesh, bark, {0, 0, 0.8f}, {-0.3f, 0.1f, 1.2f}, 0.02f);
  AppendTube(mesh, bark, {0.2f, 0, 0.8f}, {0.25f, 0.2f, 0.95f}, 0.01f);
  mesh.groups.push_back(bark);
  if (leaves) {
    Material leaf{.name = "leaves"};
    leaf.alpha_mode = AlphaMode::kMask;
    mesh.materials.push_back(leaf);
    MeshGroup cards{1, {}};
    for (const Eigen::Vector3f& tip : {Eigen::Vector3f(0.4f, 0, 1.0f), Eigen::Vector3f(-0.3f, 0.1f, 1.2f),
                                       Eigen::Vector3f(0.25f, 0.2f, 0.95f), Eigen::Vector3f(0, 0, 1)}) {
      const auto base = static_cast<uint32_t>(mesh.vertices.size());
      for (const Eigen::Vector3f& corner : {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(0.1f, 0, 0),
                                            Eigen::Vector3f(0.1f, 0, 0.1f), Eigen::Vector3f(0, 0, 0.1f)}) {
        MeshVertex v;
        v.position = tip + corner;
        v.normal = Eigen::Vector3f::UnitY();
        mesh.vertices.push_back(v);
      }
      cards.indices.insert(cards.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    mesh.groups.push_back(cards);
  }
  return mesh;
}

}  // namespace voltree::test
