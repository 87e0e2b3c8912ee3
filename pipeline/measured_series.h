// Measured data that other stages and tools leave in a workspace, read for the report's plots:
// the pruning statistics of reconstruct, and optional benchmark results as JSON (formats in
// docs/evaluate.md). Readers never invent points: a missing file gives no data.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/vtree.h"
#include "pipeline/plots.h"

namespace voltree {

struct LevelPruning {
  int level = 0;
  uint64_t billboards_before_pruning = 0;
  uint64_t billboards = 0;  // kept
  double pruned_percent = 0;
};

struct PruningStats {
  std::string source;  // the file the numbers come from (relative to the workspace when inside it)
  std::vector<LevelPruning> levels;
};

// From WORKSPACE/volume/volume.json (written by reconstruct) when it exists, else from the
// asset's per-level counts (the same numbers, carried through compress).
PruningStats ReadPruningStats(const std::filesystem::path& workspace, const VtreeAsset& asset,
                              const std::filesystem::path& asset_path);

// Series of (x, y) from a JSON benchmark file: {"points": [{X_KEY: x, Y_KEY: y, "series": name?}, ...]}
// (or the array alone). The first key of `x_keys` / `y_keys` present in a point is used; points
// are grouped into one series per "series" value (default `default_series`), sorted by x.
// Nothing when the file does not exist; Error naming the file and point when it is malformed.
std::vector<PlotSeries> ReadSeriesFile(const std::filesystem::path& file, const std::vector<std::string>& x_keys,
                                       const std::vector<std::string>& y_keys, const std::string& default_series);

}  // namespace voltree
