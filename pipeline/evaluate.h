// `voltree eval`: render a workspace's asset at the held-out truth cameras (and at the input
// cameras, for self-consistency), compare with the truth (core/image_metrics.h) for the
// renderer's own LOD ("auto", the overall figure) and for each octree level forced, and write
//   REPORT/metrics.json   every view's metrics per level and set, summaries, pruning, settings
//   REPORT/index.html     tables, side-by-side images, plots (report_html.h)
//   REPORT/eval/          held_out/NAME_{truth,voltree,difference}.png, plots/*.png (gnuplot)
// The eval/ folder is staged and renamed into place, the two files are written atomically after
// it; files of REPORT that eval did not write are never replaced without `force` (report_folder.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/image_metrics.h"
#include "core/progress.h"
#include "pipeline/error_budget.h"
#include "pipeline/evaluation_levels.h"
#include "pipeline/evaluation_truth.h"
#include "render/lod.h"

namespace voltree {

struct EvaluateOptions {
  std::filesystem::path asset;   // empty: WORKSPACE/tree.vtree
  std::filesystem::path report;  // empty: WORKSPACE/report
  // Fixed grey (8-bit units) that truth and render are composited over for the RGB metrics, the
  // alpha threshold of "covered" pixels, SSIM window. Premultiplication is set per view.
  ImageMetricsOptions metrics;
  LodOptions lod;           // the "auto" renders (screen rule, a texel per pixel)
  bool each_level = true;   // also render every octree level forced, 0..finest
  bool input_views = true;  // also compare at the input cameras (self-consistency)
  bool images = true;       // side-by-side PNGs of the held-out views
  bool plots = true;        // gnuplot PNGs (skipped with a note when gnuplot is missing)
  bool budget = false;      // also measure the error budget (error_budget.h; needs WORKSPACE/volume)
  // Judge the views from this many times the cameras' distance (SeenFromFarther): renders at
  // 1/distance of the photos' size against the truth area-resampled to it. 1: as photographed.
  double distance = 1;
  float difference_gain = 4;  // the difference images show |truth - render| x gain
  // Optional measured series for plots; empty: REPORT/codebook_sweep.json, REPORT/scene_bench.json
  // when they exist (formats in docs/evaluate.md).
  std::filesystem::path codebook_sweep;
  std::filesystem::path scene_bench;
  std::vector<std::string> notes;  // caveats the caller wants on the page and in metrics.json
  // How the workspace is named in metrics.json and on the page (default: its path); the demo
  // evaluates inside its staging folder and names the final one.
  std::string workspace_label;
  bool force = false;  // replace metrics.json / index.html / eval/ not written by eval

  std::filesystem::path AssetPath(const std::filesystem::path& workspace) const;
  std::filesystem::path ReportPath(const std::filesystem::path& workspace) const;
  void Check() const;  // throws Error naming the bad field
};

struct EvaluateResult {
  LevelMetricsTable table;
  std::vector<BudgetRow> budget;            // with options.budget
  std::optional<TruthAlignment> alignment;  // when the truth was moved into the workspace's frame
  std::filesystem::path metrics_json, index_html;
  std::vector<std::string> plots;  // drawn, relative to the report folder
  std::vector<std::string> notes;  // what was skipped and why
  std::string renderer;            // GL_RENDERER
  double render_seconds = 0;       // GL rendering of all views and levels
  double seconds = 0;              // the whole evaluation
};

// Renders WORKSPACE's asset at its truth and input cameras, compares, and writes the report.
EvaluateResult EvaluateWorkspace(const std::filesystem::path& workspace, const EvaluateOptions& options,
                                 Progress& progress);

}  // namespace voltree
