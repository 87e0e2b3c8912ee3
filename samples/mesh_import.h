// Import of tree meshes from glTF 2.0 (.gltf, .glb) and OBJ/MTL, with alpha-tested leaf textures,
// so a tree from any modeller can be photographed by the studio.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

enum class UpAxis { kY, kZ };

// "y" / "z" (either case), for command lines; nullopt otherwise.
std::optional<UpAxis> UpAxisFromName(std::string_view name);

struct MeshImportOptions {
  UpAxis up = UpAxis::kY;  // glTF is +Y up by definition; OBJ files vary
  void Check() const;
};

// Loads the file and moves it into the normalized tree frame: `up` becomes +Z and the base of
// the trunk (the centre of the lowest vertices) the origin; units are kept. Problems that do
// not stop the import (a missing texture: a flat colour is used) are appended to `warnings`.
// Throws Error naming the file for unreadable, unsupported or empty meshes.
// Supported: .gltf, .glb (samples/import_gltf.h), .obj with its .mtl (samples/import_obj.h).
// Texture coordinates follow glTF: uv (0,0) is the top-left corner of the texture, i.e. of the
// first row of its Image8 (OBJ's bottom-up v is flipped on import).
TreeMesh ImportTreeMesh(const std::filesystem::path& path, const MeshImportOptions& options,
                        std::vector<std::string>* warnings);

}  // namespace voltree
