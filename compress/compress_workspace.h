// The compress stage on a capture workspace: DIR/volume/ -> DIR/tree.vtree.
#pragma once

#include <filesystem>
#include <string>

#include "compress/compress_volume.h"
#include "core/progress.h"
#include "core/vtree.h"

namespace voltree {

struct CompressWorkspaceOptions {
  CompressOptions compress;
  std::filesystem::path output;  // empty: DIR/tree.vtree
  bool zstd = false;             // zstd-compress the asset's chunks on disk
  bool force = false;            // overwrite an existing asset
  // The asset's provenance "source"; empty: DIR's folder name. A caller working in a staging
  // folder gives the final name, so that the bytes do not depend on the staging folder's.
  std::string source_name;
};

struct CompressWorkspaceResult {
  std::filesystem::path asset;  // where it was written
  CompressStats stats;
};

// Reads DIR/volume, compresses it and writes the asset atomically; refuses an existing asset
// without `force` before any work.
CompressWorkspaceResult CompressWorkspace(const std::filesystem::path& dir, const CompressWorkspaceOptions& options,
                                          Progress& progress);

}  // namespace voltree
