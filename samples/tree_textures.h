// Procedural textures for the procedural trees: tileable bark and alpha-cut foliage atlases.
// Texture coordinates follow glTF: (0, 0) is the top-left texel, v grows down the image.
#pragma once

#include <cstdint>

#include "core/image.h"
#include "samples/tree_shape.h"

namespace voltree {

// The foliage atlas holds kFoliageCells x kFoliageCells cells, each a small cluster of leaves
// (or a needle shoot) whose stem starts at the middle of the cell's bottom edge.
constexpr int kFoliageCells = 2;

// Opaque brown bark with vertical furrows, tileable in both directions (the mesh repeats it).
Image8 MakeBarkTexture(uint64_t seed, int width = 256, int height = 512);

// RGBA with straight alpha: 255 inside the leaves, fractional on their edges (supersampled),
// 0 elsewhere. Transparent texels carry a leaf colour so filtering does not darken the edges.
Image8 MakeFoliageTexture(FoliageKind kind, uint64_t seed, int size = 256);

}  // namespace voltree
