#include "samples/procedural_tree.h"

#include <array>

#include "core/error.h"
#include "samples/tree_geometry.h"
#include "samples/tree_random.h"
#include "samples/tree_shape.h"
#include "samples/tree_skeleton.h"
#include "samples/tree_textures.h"

namespace voltree {
namespace {

struct PresetEntry {
  TreePreset preset;
  std::string_view name;
};

constexpr std::array<PresetEntry, 3> kPresets = {{
    {TreePreset::kOak, "oak"},
    {TreePreset::kPine, "pine"},
    {TreePreset::kYoungOak, "young-oak"},
}};

}  // namespace

std::string_view TreePresetName(TreePreset preset) {
  for (const PresetEntry& entry : kPresets)
    if (entry.preset == preset) return entry.name;
  Fail("unknown tree preset ", static_cast<int>(preset));
}

std::optional<TreePreset> TreePresetFromName(std::string_view name) {
  for (const PresetEntry& entry : kPresets)
    if (entry.name == name) return entry.preset;
  return std::nullopt;
}

std::vector<std::string_view> TreePresetNames() {
  std::vector<std::string_view> names;
  for (const PresetEntry& entry : kPresets) names.push_back(entry.name);
  return names;
}

void TreeOptions::Check() const {
  bool known = false;
  for (const PresetEntry& entry : kPresets) known = known || entry.preset == preset;
  if (!known) Fail("tree preset ", static_cast<int>(preset), " is not one of oak, pine, young-oak");
}

size_t LeafQuadCount(const TreeMesh& mesh) {
  size_t triangles = 0;
  for (const MeshGroup& group : mesh.groups)
    if (group.material >= 0 && group.material < static_cast<int>(mesh.materials.size()) &&
        mesh.materials[group.material].name == kLeafMaterialName)
      triangles += group.indices.size() / 3;
  return triangles / 2;
}

TreeMesh MakeProceduralTree(const TreeOptions& options) {
  options.Check();
  const TreeShape shape = PresetShape(options.preset);
  // Salted by preset so "oak 1" and "pine 1" do not share random choices.
  const uint64_t seed = HashCombine(options.seed, static_cast<uint64_t>(options.preset));
  TreeRandom random(seed);

  TreeMesh mesh;
  mesh.textures.push_back(MakeBarkTexture(HashCombine(seed, 1)));
  mesh.textures.push_back(MakeFoliageTexture(shape.foliage.kind, HashCombine(seed, 2)));

  Material bark;
  bark.name = "bark";
  bark.texture = 0;
  Material leaves;
  leaves.name = std::string(kLeafMaterialName);
  leaves.texture = 1;
  leaves.alpha_mode = AlphaMode::kMask;
  leaves.alpha_cutoff = 0.5f;
  leaves.double_sided = true;
  mesh.materials = {bark, leaves};

  const Skeleton skeleton = GrowSkeleton(shape, random);
  MeshGroup bark_group{0, {}};
  MeshGroup leaf_group{1, {}};
  AppendBranchTubes(shape, skeleton, mesh, bark_group);
  TreeRandom leaf_random = random.Fork(0x1EAF);
  AppendFoliage(shape, skeleton, leaf_random, mesh, leaf_group);
  mesh.groups.push_back(std::move(bark_group));
  if (!leaf_group.indices.empty()) mesh.groups.push_back(std::move(leaf_group));
  return mesh;
}

}  // namespace voltree
