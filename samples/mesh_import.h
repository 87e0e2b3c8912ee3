// Import of tree meshes from glTF 2.0 (.gltf, .glb) and OBJ/MTL, with alpha-tested leaf textures,
// so a tree from any modeller can be photographed by the studio.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

enum class UpAxis { kY, kZ };

struct MeshImportOptions {
  UpAxis up = UpAxis::kY;  // glTF is +Y up by definition; OBJ files vary
  void Check() const;
};

// Loads the file and moves it into the normalized tree frame: `up` becomes +Z and the base of
// the trunk (the centre of the lowest vertices) the origin; units are kept. Problems that do
// not stop the import (a missing texture: a flat colour is used) are appended to `warnings`.
// Throws Error naming the file for unreadable, unsupported or empty meshes.
TreeMesh ImportTreeMesh(const std::filesystem::path& path, const MeshImportOptions& options,
                        std::vector<std::string>* warnings);

}  // namespace voltree
