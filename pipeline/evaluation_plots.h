// The plots of the evaluation report: pruning and PSNR per octree level from the evaluation
// itself, PSNR per codebook size and frame time per tree count from measured series files when
// they exist. Only measured data is drawn (plots.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/evaluation_levels.h"
#include "pipeline/measured_series.h"
#include "pipeline/plots.h"

namespace voltree {

// `codebook_sweep` and `scene_bench`: the series files (measured_series.h) to plot.
std::vector<PlotSpec> EvaluationPlotSpecs(const LevelMetricsTable& table, const PruningStats& pruning,
                                          const std::filesystem::path& codebook_sweep,
                                          const std::filesystem::path& scene_bench);

struct DrawnPlots {
  std::vector<std::string> files;  // inside the plot folder
  std::vector<std::string> notes;  // which plots were skipped and why
};

// Draws the plots that have points into `folder` (created) with gnuplot, when it is installed.
DrawnPlots DrawPlots(const std::vector<PlotSpec>& specs, const std::filesystem::path& folder);

}  // namespace voltree
