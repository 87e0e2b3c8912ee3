#include "lod/pruned_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/error.h"

namespace voltree {

TreeMesh BuildPrunedMesh(const TreeMesh& mesh, const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws) {
  std::vector<double> scale_of(leaves.size(), 0.0);  // 0: not drawn
  for (const LeafDraw& draw : draws) {
    if (draw.leaf >= leaves.size()) Fail("lod: leaf ", draw.leaf, " out of range (", leaves.size(), " leaves)");
    if (!(draw.area_scale > 0) || !std::isfinite(draw.area_scale))
      Fail("lod: leaf area scale ", draw.area_scale, " is not positive");
    scale_of[draw.leaf] = draw.area_scale;
  }
  // Leaves of each group, in mesh order.
  std::vector<std::vector<uint32_t>> leaves_of_group(mesh.groups.size());
  for (uint32_t i = 0; i < leaves.size(); ++i) leaves_of_group[leaves[i].group].push_back(i);

  TreeMesh out;
  out.materials = mesh.materials;
  out.textures = mesh.textures;
  constexpr uint32_t kUnset = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> shared(mesh.vertices.size(), kUnset);  // non-leaf vertices, copied once
  for (size_t g = 0; g < mesh.groups.size(); ++g) {
    const MeshGroup& group = mesh.groups[g];
    MeshGroup kept{group.material, {}};
    if (leaves_of_group[g].empty()) {
      for (uint32_t index : group.indices) {
        if (shared[index] == kUnset) {
          shared[index] = static_cast<uint32_t>(out.vertices.size());
          out.vertices.push_back(mesh.vertices[index]);
        }
        kept.indices.push_back(shared[index]);
      }
    } else {
      // Each drawn leaf gets its own copy of its vertices, scaled about its centre.
      for (uint32_t i : leaves_of_group[g]) {
        if (scale_of[i] == 0) continue;
        const Leaf& leaf = leaves[i];
        const float linear = static_cast<float>(std::sqrt(scale_of[i]));
        std::unordered_map<uint32_t, uint32_t> copied;  // original vertex -> its copy
        for (uint32_t triangle : leaf.triangles)
          for (int k = 0; k < 3; ++k) {
            const uint32_t index = group.indices[3 * triangle + k];
            const auto [it, inserted] = copied.emplace(index, static_cast<uint32_t>(out.vertices.size()));
            if (inserted) {
              MeshVertex vertex = mesh.vertices[index];
              if (linear != 1) vertex.position = leaf.centre + linear * (vertex.position - leaf.centre);
              out.vertices.push_back(vertex);
            }
            kept.indices.push_back(it->second);
          }
      }
    }
    if (!kept.indices.empty()) out.groups.push_back(std::move(kept));
  }
  return out;
}

double DrawnLeafArea(const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws) {
  double total = 0;
  for (const LeafDraw& draw : draws) total += leaves.at(draw.leaf).area * draw.area_scale;
  return total;
}

}  // namespace voltree
