// The compress stage on a capture workspace: DIR/volume/ -> DIR/tree.vtree.
#pragma once

#include <filesystem>
#include <string>

#include "compress/compress_volume.h"
#include "core/progress.h"
#include "core/vtree.h"

namespace voltree {

struct CompressWorkspaceOptions {
  CompressOptions compress;      // codebooks, on-disk encoding and byte budget
  std::filesystem::path output;  // empty: DIR/tree.vtree
  bool force = false;            // overwrite an existing asset
  // The asset's provenance "source"; empty: DIR's folder name. A caller working in a staging
  // folder gives the final name, so that the bytes do not depend on the staging folder's.
  std::string source_name;
};

struct CompressWorkspaceResult {
  std::filesystem::path asset;  // where it was written
  uint64_t bytes = 0;           // its size on disk
  bool within_budget = true;    // false: over CompressOptions::max_bytes even at the smallest codebooks
  CompressOptions kept;         // the options as used: the codebook sizes the budget kept
  CompressStats stats;
};

// Reads DIR/volume, compresses it within the byte budget (compress/byte_budget.h) and writes the
// asset atomically; refuses an existing asset without `force` before any work. Over the budget
// even at the smallest codebooks, it writes the asset and warns.
CompressWorkspaceResult CompressWorkspace(const std::filesystem::path& dir, const CompressWorkspaceOptions& options,
                                          Progress& progress);

}  // namespace voltree
