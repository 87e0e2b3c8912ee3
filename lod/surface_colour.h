// The colours that points, lines and ellipsoids carry for the surfaces they replace, in linear
// RGB as the studio's shader sees them (material colour times texture times the vertex tint),
// and the texture's alpha where the leaf card is cut out.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lod/leaf_separation.h"
#include "samples/tree_mesh.h"

namespace voltree {

// The material's texel at `uv` (nearest, wrapping), linear RGB and alpha, with the base colour.
Eigen::Vector4f MaterialSample(const TreeMesh& mesh, int material, const Eigen::Vector2f& uv);

// The material's mean linear colour, texels weighted by alpha (the cut-out parts are not seen).
Eigen::Vector3f MaterialMeanColour(const TreeMesh& mesh, int material);

// Each leaf's mean colour: its material's mean times the mean tint of its corners.
std::vector<Eigen::Vector3f> LeafColours(const TreeMesh& mesh, const std::vector<Leaf>& leaves);

}  // namespace voltree
