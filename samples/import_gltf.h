// glTF 2.0 (.gltf with embedded or external buffers and images, .glb) -> TreeMesh, in the file's
// own frame (+Y up by the glTF convention); ImportTreeMesh moves it into the tree frame.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

// The default scene's node hierarchy with its transforms (matrix or TRS), every triangle
// primitive (TRIANGLES, and STRIP/FAN unrolled; others skipped with a warning), POSITION,
// NORMAL (area-weighted when absent), the TEXCOORD set the base colour texture names, COLOR_0
// as tint; pbrMetallicRoughness base colour (factor converted to sRGB) and texture, alphaMode,
// alphaCutoff, doubleSided. Images that are missing or cannot be decoded become a warning and
// a flat colour. Throws Error naming the file on parse errors and malformed accessors or indices.
TreeMesh ImportGltf(const std::filesystem::path& path, std::vector<std::string>* warnings);

}  // namespace voltree
