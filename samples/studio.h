// The photo studio: photographs a tree mesh from rings of cameras and writes a capture workspace
// with the ground truth (true cameras, mattes, foregrounds, held-out views) for evaluation.
#pragma once

#include <filesystem>

#include "core/progress.h"
#include "samples/studio_options.h"
#include "samples/tree_mesh.h"

namespace voltree {

// Writes into `workspace` (built aside, renamed into place when complete; an existing non-empty
// folder is an error unless `force`):
//   images/view_NNN.png      photos (RGB, sRGB)
//   mattes/view_NNN.png      true alpha (grey)
//   foreground/view_NNN.png  the tree alone, premultiplied RGBA
//   sparse/                  true cameras, COLMAP text (one shared camera)
//   truth/images|rgba|mattes/held_NNN.png, truth/sparse/   held-out views
//   truth/meta.json, scene.json
void PhotographTree(const TreeMesh& mesh, const StudioOptions& options, const std::filesystem::path& workspace,
                    Progress& progress, bool force = false);

}  // namespace voltree
