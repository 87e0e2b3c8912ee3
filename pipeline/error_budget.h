// `voltree eval --budget`: what each step of the pipeline costs, measured against the truth.
// For the input and the held-out views, the same metrics after each step:
//   (a) volume    the finest level's densities ray-marched (alpha only: sigma has no colour)
//   (b) billboards the finest level's uncompressed billboards, drawn as the renderer draws them
//                 (two nearest views blended; billboard_raster.h, on the CPU)
//   (c) vq        (b) with every texture replaced by its colour and alpha codewords
//   (d) dxt5      (c) as fetched from the asset's DXT5 atlas
//   (e) lod       the asset drawn by the GPU renderer with its own level of detail
// (c) recompresses the workspace's volume with the options the asset records (deterministic:
// the same codebooks as the asset's, or the budget refuses), so the codewords before DXT5 are known.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/image_metrics.h"
#include "core/progress.h"
#include "core/vtree.h"
#include "pipeline/evaluation_levels.h"
#include "pipeline/evaluation_truth.h"

namespace voltree {

struct BudgetRow {
  std::string step;  // "volume", "billboards", "vq", "dxt5", "lod"
  ViewSet set = ViewSet::kHeldOut;
  int views = 0;
  double rgb_psnr = 0;    // mean over views; NaN for the volume (alpha only)
  double alpha_psnr = 0;  // mean over views
  double precision = 0, recall = 0;
  // Recall of the visible bark and leaves alone (truth/parts/); NaN where the truth has no parts.
  double bark_recall = 0, leaf_recall = 0;
};

// The GPU renderer's image of the asset from a camera, with its own LOD (straight RGBA).
using LodRenderer = std::function<Image8(const View&)>;

// Rows (a)-(e) for both view sets.
std::vector<BudgetRow> MeasureErrorBudget(const std::filesystem::path& workspace, const VtreeAsset& asset,
                                          const std::vector<TruthView>& held_out, const std::vector<TruthView>& inputs,
                                          const ImageMetricsOptions& metrics, const LodRenderer& render_lod,
                                          Progress& progress);

// Share of the pixels where `parts` (RGB coverage) shows part `channel` (0 bark, 1 leaves) at
// least half that the render covers (alpha > threshold); NaN when the part shows nowhere.
double PartRecall(const Image8& render, const Image8& parts, int channel, float coverage_threshold);

// A plain-text table, one row per step and set, for the terminal and the README.
std::string BudgetTable(const std::vector<BudgetRow>& rows);

}  // namespace voltree
