#include "compress/asset_accounting.h"

#include <algorithm>
#include <bit>
#include <cstdio>

#include "core/error.h"

namespace voltree {
namespace {

std::string Size(uint64_t bytes) {
  char text[64];
  if (bytes >= (uint64_t(1) << 20))
    std::snprintf(text, sizeof text, "%.2f MiB", bytes / 1048576.0);
  else if (bytes >= 1024)
    std::snprintf(text, sizeof text, "%.1f KiB", bytes / 1024.0);
  else
    std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(bytes));
  return text;
}

std::string Ratio(uint64_t from, uint64_t to) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f:1", to ? double(from) / double(to) : 0.0);
  return text;
}

}  // namespace

AssetBytes CountAssetBytes(const VtreeAsset& asset, uint64_t file_bytes) {
  AssetBytes bytes;
  const uint64_t texels = uint64_t(asset.texels) * asset.texels;
  const uint64_t billboards = asset.BillboardCount();
  bytes.uncompressed_textures = billboards * texels * 4;
  bytes.vq_codebooks = uint64_t(asset.colour_codebook_size) * texels * 3 + uint64_t(asset.alpha_codebook_size) * texels;
  const uint64_t index_bits = std::bit_width(std::max(asset.colour_codebook_size, 1u) - 1) +
                              std::bit_width(std::max(asset.alpha_codebook_size, 1u) - 1);
  bytes.vq_indices = (billboards * index_bits + 7) / 8;
  bytes.gpu_atlas = asset.atlas.dxt5.size();
  // The octree and its billboards stay on the CPU: the GPU holds the atlas, the tiles' alpha
  // extents and the records of the frame being drawn (render/tree_renderer.h).
  bytes.gpu_alpha_extents = uint64_t(asset.atlas.tile_count) * sizeof(uint32_t);
  bytes.gpu_frame_records = uint64_t(asset.LeafCellCount()) * 4 * sizeof(uint32_t);
  bytes.on_disk = file_bytes;
  return bytes;
}

std::string DescribeAsset(const VtreeAsset& asset, const AssetBytes& bytes) {
  std::string out = Str("levels ", asset.levels.size(), ", branching ", asset.branching, ", billboards ", asset.texels,
                        "x", asset.texels, " texels, ", asset.views.size(), " input views\n");
  out += Str("root cube origin (", asset.origin.transpose(), ") size ", asset.size, "\n");
  out += "level  resolution      cells  billboards  before pruning  pruned\n";
  for (size_t l = 0; l < asset.levels.size(); ++l) {
    const auto& level = asset.levels[l];
    char line[160];
    const double pruned =
        level.billboards_before_pruning
            ? 100.0 * (1.0 - double(level.billboards.size()) / double(level.billboards_before_pruning))
            : 0.0;
    std::snprintf(line, sizeof line, "%5zu  %10u  %9zu  %10zu  %14llu  %5.1f%%\n", l, level.resolution,
                  level.cells.size(), level.billboards.size(),
                  static_cast<unsigned long long>(level.billboards_before_pruning), pruned);
    out += line;
  }
  out += Str("total cells ", asset.CellCount(), ", billboards ", asset.BillboardCount(), "\n");
  out += Str("codebooks: colour ", asset.colour_codebook_size, " (", asset.colour_space, "), alpha ",
             asset.alpha_codebook_size, "; atlas ", asset.atlas.width, "x", asset.atlas.height, " DXT5, ",
             asset.atlas.tile_count, " tiles\n");
  out += "bytes:\n";
  out += Str("  uncompressed RGBA8 textures  ", Size(bytes.uncompressed_textures), "\n");
  out += Str("  VQ (codebooks + indices)     ", Size(bytes.Vq()), "  (", Size(bytes.vq_codebooks), " + ",
             Size(bytes.vq_indices), ")  ", Ratio(bytes.uncompressed_textures, bytes.Vq()), "\n");
  out += Str("  GPU textures (DXT5 atlas)    ", Size(bytes.GpuTextures()), "  ",
             Ratio(bytes.uncompressed_textures, bytes.GpuTextures()), "\n");
  out += Str("  GPU resident total           ", Size(bytes.Gpu()), "  (atlas ", Size(bytes.gpu_atlas),
             ", alpha extents ", Size(bytes.gpu_alpha_extents), ", one frame's cell records at most ",
             Size(bytes.gpu_frame_records), ": ", asset.LeafCellCount(), " leaf cells)\n");
  if (bytes.on_disk) out += Str("  on disk                      ", Size(bytes.on_disk), "\n");
  return out;
}

}  // namespace voltree
