// Where the studio's tree comes from: a built-in preset grown from a seed, or a mesh file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/progress.h"
#include "samples/mesh_import.h"
#include "samples/tree_mesh.h"

namespace voltree {

struct TreeSource {
  std::string tree = "oak";  // a preset name (oak, pine, young-oak) or a .gltf/.glb/.obj file
  uint64_t seed = 1;         // presets only
  UpAxis up = UpAxis::kY;    // mesh files only
};

bool IsTreeMeshFile(const std::string& name);
// "oak, pine, young-oak", for messages and --help.
std::string TreePresetList();
// The name recorded in truth/meta.json: the preset, or the mesh file's name.
std::string TreeSourceName(const TreeSource& source);

// Grows the preset or imports the file; import warnings go to `warnings`. Throws Error for an
// unknown preset (listing the presets) or a bad file.
TreeMesh LoadTreeMesh(const TreeSource& source, Progress& progress, std::vector<std::string>* warnings);

}  // namespace voltree
