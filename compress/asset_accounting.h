// Where the bytes of a compressed tree go (Linz 2006 section 6), for `voltree info` and benches.
#pragma once

#include <cstdint>
#include <string>

#include "core/vtree.h"

namespace voltree {

struct AssetBytes {
  uint64_t uncompressed_textures = 0;  // every billboard as n x n RGBA8
  uint64_t vq_codebooks = 0;           // colour codewords as RGB8 + alpha codewords as A8
  uint64_t vq_indices = 0;             // (colour, alpha) index pair per billboard, as narrow as the
                                       // codebooks allow (the .vtree BBRD index streams)
  uint64_t gpu_atlas = 0;              // DXT5 atlas
  uint64_t gpu_alpha_extents = 0;      // 4 bytes per atlas tile (render/alpha_extent.h)
  uint64_t gpu_frame_records = 0;      // the most one frame uploads: 16 bytes per cell drawn, at most
                                       // one per leaf cell (render/frame_record.h)
  uint64_t on_disk = 0;                // the .vtree file (0 when unknown)

  uint64_t Vq() const { return vq_codebooks + vq_indices; }
  // What replaces the RGBA8 textures on the GPU. The (colour, alpha) indices live in the billboard
  // records, which an uncompressed renderer needs too (for atlas coordinates), so they count there.
  uint64_t GpuTextures() const { return gpu_atlas; }
  uint64_t Gpu() const { return gpu_atlas + gpu_alpha_extents + gpu_frame_records; }
};

AssetBytes CountAssetBytes(const VtreeAsset& asset, uint64_t file_bytes = 0);

// A human-readable table: levels, cells and billboards per level, views, codebooks, bytes.
std::string DescribeAsset(const VtreeAsset& asset, const AssetBytes& bytes);

}  // namespace voltree
