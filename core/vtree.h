// The .vtree asset: a compressed volumetric tree, ready for the renderer.
//
// Layout (little-endian), format version 2:
//   "VTREE\0\0\0"  u32 format version (kVtreeFormatVersion)
//   chunks, in this order: HEAD, ATLS, then CELL and BBRD for every level (root first). Progressive:
//   a prefix of the file that ends after level K's BBRD holds everything levels 0..K draw with.
//   Each chunk: char tag[4], u32 encoding (0 raw, 1 zstd), u64 stored size, u64 raw size,
//   u32 CRC-32 of (tag, encoding, sizes, stored payload), then the stored payload.
//   HEAD  JSON (UTF-8): levels, branching, texels, root cube, views, codebooks, bounds, provenance.
//   ATLS  u32 width, u32 height, u32 tile pitch, u32 tiles per row, u32 tile count,
//         width * height bytes of DXT5 blocks (row-major blocks).
//   CELL  u32 level, u32 resolution, u32 n, u8 cell coding, then
//           coding 0 (explicit): n x u16[3] cell coordinates;
//           coding 1 (child masks, only below level 0): for each cell of the level above, in its
//             order, ceil(b^3 / 8) bytes of a mask whose bit x + b * (y + b * z) marks the child at
//             offset (x, y, z); the level's cells are those children sorted by (z, y, x);
//         then n x f32 density as 4 byte planes (every cell's byte 0, then every byte 1, ...).
//   BBRD  u32 level, u64 billboards before pruning, u32 m, u8 colour index bits, u8 alpha index bits
//         (bit_width(codebook size - 1) each), then bit streams, each padded to a whole byte:
//           view masks: n x V bits, cell-major; bit (c * V + v) says cell c has view v's billboard;
//           m colour indices, then m alpha indices, in (cell, view) order. An index stream of k
//             bits: k <= 8, k-bit fields; k > 8, m low bytes, then m fields of the high k - 8 bits.
//   Bit streams are least significant bit first (core/bit_stream.h). Cell and view of a billboard
//   are implicit in the view masks, which is why billboards are sorted by (cell, view).
//   Version 1 (10-byte billboard records, atlas last) is refused with a message to rebuild.
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

constexpr uint32_t kVtreeFormatVersion = 2;

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
  // Cells with no child in the next level: the most cells one frame can draw, since a frame draws
  // a cut of the octree and no cut has more cells than there are leaves.
  size_t LeafCellCount() const;
};

struct VtreeWriteOptions {
  bool zstd = false;  // compress chunk payloads (not HEAD) with zstd, each only where that makes it smaller
  int zstd_level = 19;
  bool force = false;  // overwrite an existing file
};

// What a read left out: levels beyond VtreeReadOptions::max_level, or beyond the end of a
// truncated (progressively downloaded) file when VtreeReadOptions::allow_partial.
struct VtreeLoadReport {
  uint32_t levels_in_file = 0;  // as HEAD declares
  uint32_t levels_loaded = 0;
  bool truncated = false;  // the bytes end before the last level wanted
  uint64_t file_bytes = 0;
  std::string missing;  // when truncated: which levels and where the file ends
};

struct VtreeReadOptions {
  bool verify_checksums = true;  // the fuzzer turns this off to reach the parsers behind the CRC
  // A file cut off after some whole level (HEAD, ATLS and level 0 at least) loads the whole levels
  // and says what is missing in `report`, instead of failing.
  bool allow_partial = false;
  int max_level = -1;                 // finest level to load (coarser levels only); -1: all
  VtreeLoadReport* report = nullptr;  // filled when given
  void Check() const;
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
  uint64_t offset = 0;
  uint64_t stored_bytes = 0;   // in the file, the chunk's header included
  uint64_t payload_bytes = 0;  // stored_bytes less the header: what zstd (or nothing) made of raw_bytes
  uint64_t raw_bytes = 0;      // the payload decoded
  bool zstd = false;
  bool complete = true;  // false: cut off by the end of the file (only with allow_partial; then last)
};
std::vector<VtreeChunkInfo> ListChunks(std::string_view bytes, const std::string& name, bool allow_partial = false);

}  // namespace voltree
