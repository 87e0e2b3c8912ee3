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

// The tree in the normalized frame: +Z up, trunk base at the origin, metres.
TreeMesh MakeProceduralTree(const TreeOptions& options);

}  // namespace voltree
