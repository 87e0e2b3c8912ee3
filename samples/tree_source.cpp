#include "samples/tree_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "core/error.h"
#include "samples/procedural_tree.h"

namespace voltree {

bool IsTreeMeshFile(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension == ".gltf" || extension == ".glb" || extension == ".obj";
}

std::string TreePresetList() {
  std::string list;
  for (std::string_view name : TreePresetNames()) list += Str(list.empty() ? "" : ", ", name);
  return list;
}

std::string TreeSourceName(const TreeSource& source) {
  return IsTreeMeshFile(source.tree) ? std::filesystem::path(source.tree).filename().string() : source.tree;
}

TreeMesh LoadTreeMesh(const TreeSource& source, Progress& progress, std::vector<std::string>* warnings) {
  if (IsTreeMeshFile(source.tree)) {
    progress.Say("tree", "importing " + source.tree);
    MeshImportOptions options;
    options.up = source.up;
    return ImportTreeMesh(source.tree, options, warnings);
  }
  const std::optional<TreePreset> preset = TreePresetFromName(source.tree);
  if (!preset)
    Fail("--tree '", source.tree, "': unknown preset (expected one of ", TreePresetList(),
         ") and not a .gltf, .glb or .obj file");
  TreeOptions options;
  options.preset = *preset;
  options.seed = source.seed;
  progress.Say("tree", Str("growing a procedural ", source.tree, " (seed ", source.seed, ")"));
  return MakeProceduralTree(options);
}

}  // namespace voltree
