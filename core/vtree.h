// The .vtree asset: a compressed volumetric tree, ready for the renderer.
//
// Layout (little-endian):
//   "VTREE\0\0\0"  u32 format version (kVtreeFormatVersion)
//   chunks, in this order: HEAD, then CELL and BBRD for every level (root first), then ATLS.
//   Each chunk: char tag[4], u32 encoding (0 raw, 1 zstd), u64 stored size, u64 raw size,
//   u32 CRC-32 of (tag, encoding, sizes, stored payload), then the stored payload.
//   HEAD  JSON (UTF-8): levels, branching, texels, root cube, views, codebooks, bounds, provenance.
//   CELL  u32 level, u32 resolution, u32 n, n x u16[3] cell coordinates, n x f32 density.
//   BBRD  u32 level, u64 billboards before pruning, u32 m,
//         m x {u32 cell, u16 view, u16 colour codeword, u16 alpha codeword}.
//   ATLS  u32 width, u32 height, u32 tile pitch, u32 tiles per row, u32 tile count,
//         width * height bytes of DXT5 blocks (row-major blocks).
//
// The atlas holds tile i at ((i % tiles_per_row) * pitch, (i / tiles_per_row) * pitch): RGB is
// colour codeword i, A is alpha codeword i, both n x n texels in the top-left of the tile. A
// billboard draws RGB from tile `colour` and A from tile `alpha`. RGB is straight (not
// premultiplied) sRGB: DXT interpolates colour and alpha in separate blocks here, and colour and
// alpha of one billboard live in different tiles, so the shader premultiplies after fetching.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace voltree {

constexpr uint32_t kVtreeFormatVersion = 1;

struct VtreeBillboard {
  uint32_t cell = 0;    // index into VtreeLevel::cells
  uint16_t view = 0;    // index into VtreeAsset::views
  uint16_t colour = 0;  // colour codeword = atlas tile for RGB
  uint16_t alpha = 0;   // alpha codeword = atlas tile for A
};

struct VtreeLevel {
  uint32_t resolution = 1;                     // cells per axis: branching^level
  std::vector<std::array<uint16_t, 3>> cells;  // integer cell coordinates
  std::vector<float> density;                  // sigma per cell, per unit length
  std::vector<VtreeBillboard> billboards;      // sorted by (cell, view); pruned ones absent
  uint64_t billboards_before_pruning = 0;
};

struct VtreeView {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

struct VtreeAtlas {
  uint32_t width = 0, height = 0;  // texels, multiples of 4
  uint32_t tile_pitch = 4;         // texels per tile side: the billboard size rounded up to 4
  uint32_t tiles_per_row = 0;
  uint32_t tile_count = 0;    // max(colour codebook, alpha codebook)
  std::vector<uint8_t> dxt5;  // width * height bytes

  // Top-left texel of tile i.
  std::array<uint32_t, 2> TileOrigin(uint32_t tile) const {
    return {(tile % tiles_per_row) * tile_pitch, (tile / tiles_per_row) * tile_pitch};
  }
};

struct VtreeAsset {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // min corner of the root cube
  double size = 1;                                   // root cube edge
  int branching = 2;
  int texels = 4;                                        // n: billboards are n x n
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero();  // of the kept finest cells
  Eigen::Vector3d bounds_max = Eigen::Vector3d::Zero();
  std::vector<VtreeView> views;
  std::vector<VtreeLevel> levels;
  uint32_t colour_codebook_size = 0;
  uint32_t alpha_codebook_size = 0;
  std::string colour_space = "lab";  // where the colour codebook was built
  VtreeAtlas atlas;
  nlohmann::json provenance = nlohmann::json::object();  // tool, options, source; no timestamps

  size_t BillboardCount() const;
  size_t CellCount() const;
};

struct VtreeWriteOptions {
  bool zstd = false;  // compress chunk payloads (not HEAD) with zstd
  int zstd_level = 19;
  bool force = false;  // overwrite an existing file
};

struct VtreeReadOptions {
  bool verify_checksums = true;  // the fuzzer turns this off to reach the parsers behind the CRC
};

// Largest decompressed chunk a reader accepts, so that a corrupt size cannot allocate absurdly.
constexpr uint64_t kVtreeMaxChunkBytes = uint64_t(1) << 30;

std::string SerializeAsset(const VtreeAsset& asset, const VtreeWriteOptions& options = {});
// `name` prefixes error messages ("tree.vtree: chunk BBRD at byte 1234: checksum mismatch").
VtreeAsset ParseAsset(std::string_view bytes, const std::string& name, const VtreeReadOptions& options = {});

// Atomic (temporary + rename); refuses to overwrite without options.force.
void WriteAsset(const std::filesystem::path& path, const VtreeAsset& asset, const VtreeWriteOptions& options = {});
VtreeAsset ReadAsset(const std::filesystem::path& path, const VtreeReadOptions& options = {});

// Per-chunk sizes as stored, for `voltree info`.
struct VtreeChunkInfo {
  std::string tag;
  uint64_t offset = 0, stored_bytes = 0, raw_bytes = 0;
  bool zstd = false;
};
std::vector<VtreeChunkInfo> ListChunks(std::string_view bytes, const std::string& name);

}  // namespace voltree
