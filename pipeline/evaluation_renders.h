// The render loop of `voltree eval`: every truth view rendered at every level choice on the GL
// thread, each render compared with its truth on worker threads while the next view renders, and
// the side-by-side images of the held-out views (auto LOD) written into the staged eval/ folder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/image_metrics.h"
#include "core/progress.h"
#include "pipeline/evaluation_levels.h"
#include "pipeline/evaluation_truth.h"
#include "render/lod.h"
#include "render/tree_renderer.h"

namespace voltree {

// What every view's renders share.
struct EvaluationRenderSettings {
  std::vector<LevelChoice> choices;
  ImageMetricsOptions metrics;  // premultiplication is set per view
  LodOptions lod;               // the auto renders
  bool images = true;           // side-by-side PNGs of the held-out views
  float difference_gain = 4;
  std::filesystem::path staging;  // the staged REPORT/eval/ folder the images go to
};

// The side-by-side images of one held-out view, relative to the report folder.
struct ComparisonFiles {
  std::string view;  // the view's image name
  std::string truth, render, difference;
  std::string interactive;       // the web page at this view's camera (report_html.h), or empty
  int interactive_height = 256;  // its frame's height for a width of 256
};

struct EvaluationRenders {
  LevelMetricsTable table;                   // every view at every level choice
  std::vector<ComparisonFiles> comparisons;  // the held-out views, in order, when images are on
  double render_seconds = 0;                 // GL rendering alone
};

// held_out/a/b.png -> "a_b": report file names are flat.
std::string FlatStem(const std::string& view_name);

EvaluationRenders RenderAndCompare(const std::vector<TruthView>& held_out, const std::vector<TruthView>& inputs,
                                   const EvaluationRenderSettings& settings, TreeRenderer& renderer,
                                   Progress& progress);

}  // namespace voltree
