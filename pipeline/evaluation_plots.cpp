#include "pipeline/evaluation_plots.h"

#include <optional>

#include "core/error.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

PlotSpec MakePlot(std::string file, std::string title, std::string x_label, std::string y_label) {
  PlotSpec spec;
  spec.file = std::move(file), spec.title = std::move(title);
  spec.x_label = std::move(x_label), spec.y_label = std::move(y_label);
  return spec;
}

}  // namespace

std::vector<PlotSpec> EvaluationPlotSpecs(const LevelMetricsTable& table, const PruningStats& pruning,
                                          const fs::path& codebook_sweep, const fs::path& scene_bench) {
  std::vector<PlotSpec> specs;
  PlotSpec pruned =
      MakePlot("pruned_per_level.png", "Billboards pruned per level (reconstruct)", "octree level", "pruned %");
  pruned.style = PlotStyle::kBars, pruned.integer_x = true;
  PlotSeries pruned_series{"pruned %", {}};
  for (const LevelPruning& level : pruning.levels) pruned_series.points.emplace_back(level.level, level.pruned_percent);
  pruned.series.push_back(pruned_series);
  specs.push_back(pruned);

  PlotSpec psnr =
      MakePlot("psnr_per_level.png", "RGB PSNR per forced level (over grey)", "octree level", "RGB PSNR (dB)");
  psnr.integer_x = true;
  const auto rgb = [](const ViewMetrics& m) { return m.rgb_psnr; };
  const auto alpha = [](const ViewMetrics& m) { return m.alpha_psnr; };
  auto to_points = [](const std::vector<std::pair<int, double>>& in) {
    std::vector<std::pair<double, double>> out;
    for (const auto& [x, y] : in) out.emplace_back(x, y);
    return out;
  };
  psnr.series = {{"held-out views", to_points(table.MeanPerLevel(ViewSet::kHeldOut, rgb))},
                 {"input views", to_points(table.MeanPerLevel(ViewSet::kInput, rgb))}};
  specs.push_back(psnr);
  PlotSpec alpha_psnr = psnr;
  alpha_psnr.file = "alpha_psnr_per_level.png", alpha_psnr.title = "Alpha PSNR per forced level";
  alpha_psnr.y_label = "alpha PSNR (dB)";
  alpha_psnr.series = {{"held-out views", to_points(table.MeanPerLevel(ViewSet::kHeldOut, alpha))},
                       {"input views", to_points(table.MeanPerLevel(ViewSet::kInput, alpha))}};
  specs.push_back(alpha_psnr);

  PlotSpec codebook =
      MakePlot("psnr_vs_codebook.png", "PSNR vs colour codebook size", "colour codebook size", "PSNR (dB)");
  codebook.log_x = true;
  codebook.series = ReadSeriesFile(codebook_sweep, {"codebook", "colour_codebook", "codebook_size"},
                                   {"rgb_psnr", "psnr", "psnr_db"}, "PSNR");
  specs.push_back(codebook);

  PlotSpec scene =
      MakePlot("ms_per_frame_vs_trees.png", "Frame time vs trees in the scene", "trees", "ms per frame (median)");
  scene.series = ReadSeriesFile(scene_bench, {"trees", "instances"}, {"median_ms", "ms_per_frame"}, "median ms");
  specs.push_back(scene);
  return specs;
}

DrawnPlots DrawPlots(const std::vector<PlotSpec>& specs, const fs::path& folder) {
  DrawnPlots drawn;
  fs::create_directories(folder);
  std::string why_not;
  const fs::path probe_log = folder / "gnuplot_probe.log";
  const std::optional<Gnuplot> gnuplot = FindGnuplot(probe_log, &why_not);
  std::error_code ignored;
  fs::remove(probe_log, ignored);
  if (!gnuplot) {
    drawn.notes.push_back("plots skipped: " + why_not);
    return drawn;
  }
  for (const PlotSpec& spec : specs) {
    if (!spec.HasPoints()) continue;  // only measured data is plotted
    try {
      DrawPlot(*gnuplot, spec, folder);
      drawn.files.push_back(spec.file);
    } catch (const Error& error) {
      drawn.notes.push_back(Str("plot ", spec.file, " skipped: ", error.what()));
    }
  }
  return drawn;
}

}  // namespace voltree
