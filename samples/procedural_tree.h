// Procedural trees: a seeded branching skeleton with tapered, bark-textured branches and
// alpha-textured leaf quads. Same options and seed -> the same mesh, bit for bit.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

enum class TreePreset {
  kOak,       // dense broad crown, at least 20k leaves
  kPine,      // conical, needle clusters
  kYoungOak,  // sparse, at most 3k leaves
};

std::string_view TreePresetName(TreePreset preset);
std::optional<TreePreset> TreePresetFromName(std::string_view name);
std::vector<std::string_view> TreePresetNames();

struct TreeOptions {
  TreePreset preset = TreePreset::kOak;
  uint64_t seed = 1;
  void Check() const;
};

// The tree in the normalized frame: +Z up, trunk base at the origin, metres. Materials: "bark"
// (opaque, tiling texture) and kLeafMaterialName (alpha mask, double sided; one quad per cluster).
TreeMesh MakeProceduralTree(const TreeOptions& options);

// The material name of leaf (or needle) quads, so counts can be reported for any mesh.
inline constexpr std::string_view kLeafMaterialName = "leaves";

// Quads (triangle pairs) drawn with the material named kLeafMaterialName.
size_t LeafQuadCount(const TreeMesh& mesh);

}  // namespace voltree
