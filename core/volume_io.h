// `DIR/volume/` on disk: the reconstruction handed from reconstruct/ to compress/ and render/.
//
// Two files, written together through a StagedDirectory (the folder appears whole or not at all):
//   volume.json  small, human-readable: format/version, root cube, branching, texels, the input
//                views (name, position, direction, up), per-level statistics (cells, billboards
//                before/after pruning, percent pruned) and the provenance (options used).
//   volume.bin   little-endian binary:
//                  char[8]  magic "VTVOLBIN"
//                  uint32   version (2; version 1 ended with FNV-1a 64 and is refused with a
//                           message to reconstruct again)
//                  uint32   texels n, uint32 branching, uint32 level count L, uint32 view count V
//                  L x { uint32 resolution, uint64 cells, uint64 billboards,
//                        uint64 billboards_before_pruning }
//                  for each level:
//                    cells      x uint16[3]  integer cell coordinates (x, y, z), sorted by (z, y, x)
//                    cells      x float32    density sigma per unit length of the tree frame
//                    billboards x { uint32 cell, uint16 view }  sorted by (cell, view)
//                    billboards x n*n*4 uint8  RGBA8 texels, sRGB, premultiplied alpha, row-major,
//                                              texel (0,0) at the top-left seen from the view
//                  uint32   CRC-32 (core/crc32.h, as in .vtree) of every byte before it
// ReadVolume checks the magic, the version (before the checksum), the checksum, every count
// against the bytes present and every index, and agrees the JSON with the binary; errors name
// the file and what was expected.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/volume.h"

namespace voltree {

inline constexpr const char* kVolumeJsonName = "volume.json";
inline constexpr const char* kVolumeBinName = "volume.bin";

// Throws Error when the volume is inconsistent (sizes, indices, order); used before writing and
// after reading.
void CheckVolume(const Volume& volume, const std::string& where);

// Percent of billboards removed by pruning at a level (0 when there were none).
double PrunedPercent(const VolumeLevel& level);

// The bytes of volume.bin and the document of volume.json; exposed for tests and tools.
std::string EncodeVolumeBinary(const Volume& volume);
nlohmann::json VolumeJson(const Volume& volume, const nlohmann::json& provenance);

// Writes `folder` (normally DIR/volume) atomically. An existing non-empty folder is an error
// unless `force`. `provenance` (e.g. the reconstruction options) is stored as is in volume.json.
void WriteVolume(const std::filesystem::path& folder, const Volume& volume,
                 const nlohmann::json& provenance = nlohmann::json::object(), bool force = false);

// Reads and validates a folder written by WriteVolume.
Volume ReadVolume(const std::filesystem::path& folder);

}  // namespace voltree
