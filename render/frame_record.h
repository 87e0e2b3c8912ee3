// One drawn cell as the billboard shader reads it: 16 bytes that carry everything the GPU needs of
// the cell and of its two billboards. The GPU therefore keeps no per-cell or per-billboard table of
// the asset, only the DXT5 atlas, the alpha extents and one frame's records; the CPU traversal,
// which already looks up each drawn cell's billboards, writes their tiles into the record.
//   x  cell coordinates i | j << 10 | k << 20 (10 bits each: at most 1024 cells per axis)
//   y  view A's billboard tiles, colour | alpha << 16 (0 when absent)
//   z  view B's billboard tiles, the same
//   w  level | presence << 8 (bit 0: A present, bit 1: B present)
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vtree.h"

namespace voltree {

using FrameRecord = std::array<uint32_t, 4>;  // at most VtreeAsset::LeafCellCount() per frame

constexpr uint32_t kMaxCellsPerAxis = 1024;  // 10 bits per coordinate
constexpr int kMaxRenderedLevels = 11;       // branching 2 reaches 1024 per axis at level 10

// Per cell, level by level in storage order (OctreeIndex's global numbering), its coordinates
// packed as record.x. Throws Error naming the level when one is finer than kMaxCellsPerAxis.
std::vector<uint32_t> PackCellCoordinates(const VtreeAsset& asset);

// A billboard's tiles as record.y / record.z hold them; 0 for no billboard.
inline uint32_t PackTiles(const VtreeBillboard* billboard) {
  return billboard ? uint32_t(billboard->colour) | uint32_t(billboard->alpha) << 16 : 0u;
}

inline FrameRecord MakeFrameRecord(uint32_t cell_code, int level, const VtreeBillboard* a, const VtreeBillboard* b) {
  const uint32_t presence = (a ? 1u : 0u) | (b ? 2u : 0u);
  return {cell_code, PackTiles(a), PackTiles(b), uint32_t(level) | presence << 8};
}

}  // namespace voltree
