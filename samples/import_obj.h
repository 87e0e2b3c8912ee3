// Wavefront OBJ + MTL -> TreeMesh, in the file's own frame; ImportTreeMesh moves it into the
// tree frame. Polygons are triangulated (fans); v of `vt` is flipped to the TreeMesh convention.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "samples/tree_mesh.h"

namespace voltree {

// Materials: `Kd` (sRGB as stored) and `d` (opacity; below 1 -> kBlend); `map_Kd` replaces Kd
// (Blender's importer does the same: exporters write Kd 0.8 next to a texture); `map_d` (grey,
// or the alpha of an RGBA image) multiplies the texture's alpha. A material whose texture ends
// with any transparent texel is an alpha-tested leaf: kMask, cutoff 0.5, double-sided. Missing
// texture files become warnings and a flat colour. Normals come from `vn`, else area-weighted.
TreeMesh ImportObj(const std::filesystem::path& path, std::vector<std::string>* warnings);

}  // namespace voltree
