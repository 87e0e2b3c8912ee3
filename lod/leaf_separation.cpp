#include "lod/leaf_separation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <tuple>

#include "lod/disjoint_sets.h"

namespace voltree {

bool IsLeafMaterial(const Material& material) {
  return material.alpha_mode != AlphaMode::kOpaque || material.name == "leaves";
}

std::vector<Leaf> SeparateLeaves(const TreeMesh& mesh) {
  std::vector<Leaf> leaves;
  DisjointSets<uint32_t> sets(mesh.vertices.size());
  // Unwelded cards: vertices at the same position belong together.
  std::map<std::tuple<float, float, float>, uint32_t> first_at;
  for (const MeshGroup& group : mesh.groups) {
    if (!IsLeafMaterial(mesh.materials[group.material])) continue;
    for (size_t corner = 0; corner < group.indices.size(); ++corner) {
      const uint32_t index = group.indices[corner];
      if (corner % 3 != 0) sets.Join(group.indices[corner - corner % 3], index);
      const Eigen::Vector3f& p = mesh.vertices[index].position;
      const auto [it, inserted] = first_at.emplace(std::make_tuple(p.x(), p.y(), p.z()), index);
      if (!inserted) sets.Join(it->second, index);
    }
  }
  for (size_t g = 0; g < mesh.groups.size(); ++g) {
    const MeshGroup& group = mesh.groups[g];
    if (!IsLeafMaterial(mesh.materials[group.material])) continue;
    std::map<uint32_t, size_t> leaf_of_root;  // root vertex -> index in `leaves`
    for (uint32_t triangle = 0; triangle < group.indices.size() / 3; ++triangle) {
      const uint32_t root = sets.Find(group.indices[3 * triangle]);
      const auto [it, inserted] = leaf_of_root.emplace(root, leaves.size());
      if (inserted) leaves.push_back(Leaf{static_cast<int>(g), {}, Eigen::Vector3f::Zero(), 0});
      leaves[it->second].triangles.push_back(triangle);
    }
  }
  for (Leaf& leaf : leaves) {
    const MeshGroup& group = mesh.groups[leaf.group];
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero(), mean = Eigen::Vector3d::Zero();
    for (uint32_t triangle : leaf.triangles) {
      const Eigen::Vector3d a = mesh.vertices[group.indices[3 * triangle]].position.cast<double>();
      const Eigen::Vector3d b = mesh.vertices[group.indices[3 * triangle + 1]].position.cast<double>();
      const Eigen::Vector3d c = mesh.vertices[group.indices[3 * triangle + 2]].position.cast<double>();
      const double area = 0.5 * (b - a).cross(c - a).norm();
      leaf.area += area;
      weighted += area * (a + b + c) / 3;
      mean += (a + b + c) / 3;
    }
    // Degenerate leaves (no area) keep the plain mean of their triangles.
    leaf.centre = (leaf.area > 0 ? Eigen::Vector3d(weighted / leaf.area)
                                 : Eigen::Vector3d(mean / static_cast<double>(leaf.triangles.size())))
                      .cast<float>();
  }
  return leaves;
}

double TotalLeafArea(const std::vector<Leaf>& leaves) {
  double total = 0;
  for (const Leaf& leaf : leaves) total += leaf.area;
  return total;
}

}  // namespace voltree
