#include "lod/lod_bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "lod/stochastic_pruning.h"
#include "pipeline/plots.h"

namespace voltree {
namespace {

std::string Fixed(double value, int digits) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

// JSON has no infinity: identical images' PSNR is written as null.
nlohmann::json Number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

// Methods that draw no pruned leaves have no lambda or leaf scale.
bool Leafless(const std::string& method) { return method == "asset" || method == "points" || method == "ellipsoids"; }

}  // namespace

std::string LodBenchTable(const LodBenchResult& result) {
  std::string text = Str(
      "# LOD bench: ", result.tree, "\n\n", result.leaf_count, " leaves, ", result.triangle_count, " triangles; ",
      result.views, " views per size (the studio's held-out ring and top views); renderer: ", result.renderer, "\n\n");
  for (const std::string& note : result.notes) text += "Note: " + note + "\n\n";
  text +=
      "| method | size px | lambda | area scale | leaves | triangles | primitives | GPU KiB | draw ms | fragments | "
      "precision | recall | PR score | MS-RMS | RGB PSNR | alpha PSNR |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const LodBenchRow& row : result.rows) {
    const std::string fragments = row.fragments < 0 ? "not available" : std::to_string(row.fragments);
    // The asset has cells and billboards, not leaves: no lambda, scale or leaf count; points and
    // ellipsoids draw leaves only where they fall back to the mesh.
    const bool asset = row.method == "asset", leafless = Leafless(row.method);
    // Points: lambda is the drawn share of the sampled points; ellipsoids: k, the clusters of the
    // level drawn, and the calibrated scale of their semi-axes.
    const std::string lambda = row.method == "ellipsoids" ? Str("k ", row.level)
                               : asset                    ? std::string("-")
                                                          : Fixed(row.lambda, 4);
    const std::string scale = row.method == "ellipsoids" || !leafless ? Fixed(row.area_scale, 2) : "-";
    text +=
        Str("| ", row.method, " | ", row.size, " | ", lambda, " | ", scale, " | ",
            asset ? "-" : std::to_string(row.leaves), " | ", row.triangles, " | ", row.primitives, " | ",
            Fixed((row.geometry_bytes + row.texture_bytes) / 1024.0, 0), " | ", Fixed(row.draw_ms, 2), " | ", fragments,
            " | ", Fixed(row.precision, 4), " | ", Fixed(row.recall, 4), " | ", Fixed(row.pr_score, 4), " | ",
            Fixed(row.multiscale_rms, 4), " | ", Fixed(row.rgb_psnr, 2), " | ", Fixed(row.alpha_psnr, 2), " |\n");
  }
  if (!result.scale_searches.empty()) {
    text += Str("\n## Neubert's PR-optimal scale (preprocessing on the input views, ",
                Fixed(result.preprocess_seconds, 1), " s)\n\n",
                "| order | size px | lambda | Cook s = 1/lambda | PR score at Cook's s | s_opt | PR score at s_opt |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    for (const ScaleSearch& search : result.scale_searches) {
      // Cook's scale is the candidate lambda^-1 (t = 1); the nearest one is reported.
      const ScaleTrial& cook = NearestTrial(search.trials, 1 / search.lambda);
      text += Str("| ", search.method == "neubert" ? "random" : "priority", " | ", search.size, " | ",
                  Fixed(search.lambda, 4), " | ", Fixed(cook.area_scale, 2), " | ",
                  Fixed(PrScore(cook.precision, cook.recall), 4), " | ", Fixed(search.best.area_scale, 2), " | ",
                  Fixed(PrScore(search.best.precision, search.best.recall), 4), " |\n");
    }
    text += Str("\nRendering priority order (preprocessing): ", Fixed(result.priority_seconds, 2), " s\n");
  }
  if (!result.level_selections.empty()) {
    text += Str("\n## Neubert's detail level selection (input views, ", Fixed(result.level_selection_seconds, 1),
                " s): the smallest lambda whose priority order and PR-optimal scale match Cook's PR score\n\n",
                "| size px | lambda Cook | PR score Cook | levels tried (lambda: score) | lambda matched | s_opt |\n"
                "|---:|---:|---:|---|---:|---:|\n");
    for (const LevelSelection& selection : result.level_selections) {
      std::string tried;
      for (const LevelSample& sample : selection.samples)
        tried += Str(tried.empty() ? "" : ", ", Fixed(sample.lambda, 3), ": ", Fixed(sample.quality, 3));
      text +=
          Str("| ", selection.size, " | ", Fixed(selection.cook_lambda, 4), " | ", Fixed(selection.target, 4), " | ",
              tried, " | ", Fixed(selection.matched.lambda, 4), " | ", Fixed(selection.matched.area_scale, 2), " |\n");
    }
  }
  if (result.vmi_seconds > 0)
    text += Str("\nVMI removal sequence (preprocessing, id renders of the input views): ", Fixed(result.vmi_seconds, 1),
                " s\n");
  text +=
      "\nSizes: the tree framed as in the studio's photos, in an image that many pixels tall. lambda = "
      "max(min_lambda, (size / frame)^2). GPU KiB: vertex, index and texture buffers. Draw ms: median over the views, "
      "both passes at the supersampled resolution. PSNR inf: identical to the full mesh.\n";
  if (!result.ellipsoid_levels.empty() || result.points_seconds > 0) {
    text += Str("\nPrimitives (preprocessing): branch skeleton from the bark in ", Fixed(result.skeleton_seconds, 2),
                " s (", result.skeleton_segments, " segments); ", result.sampled_points, " points sampled in ",
                Fixed(result.points_seconds, 2), " s; ellipsoids (the EM fits of every level) in ",
                Fixed(result.ellipsoid_seconds, 2), " s; branch lines merged in ", Fixed(result.line_merge_seconds, 2),
                " s. Ellipsoid levels (clusters asked: kept):");
    for (size_t l = 0; l < result.ellipsoid_levels.size(); ++l)
      text += Str(l ? ", " : " ", result.ellipsoid_levels[l], ": ", result.ellipsoid_counts[l]);
    text += ".\n";
  }
  if (!result.ellipsoid_calibrations.empty()) {
    text += Str("\n## Ellipsoid size calibrated by image error (Clasen et al.; input views, ",
                Fixed(result.ellipsoid_calibration_seconds, 1), " s)\n\n",
                "| size px | clusters | MS-RMS at scale 1 | scale | MS-RMS at scale |\n|---:|---:|---:|---:|---:|\n");
    for (const EllipsoidCalibration& calibration : result.ellipsoid_calibrations) {
      double unscaled = 0;
      for (const auto& [scale, ms_rms] : calibration.trials)
        if (scale == 1.0) unscaled = ms_rms;
      text += Str("| ", calibration.size, " | ", calibration.clusters, " | ", Fixed(unscaled, 4), " | ",
                  Fixed(calibration.scale, 2), " | ", Fixed(calibration.ms_rms, 4), " |\n");
    }
  }
  const auto has = [&result](const char* method) {
    return std::find(result.methods.begin(), result.methods.end(), method) != result.methods.end();
  };
  if (has("points"))
    text +=
        "points: Deussen et al. 2002, a prefix of the points and lines (primitives; lambda: the share of the "
        "sampled points drawn; lines drawn as 2 triangles each), or the mesh itself (leaves, triangles) where the "
        "size asks for more points than were sampled.\n";
  if (has("ellipsoids"))
    text +=
        "ellipsoids: Clasen et al., the level of k EM clusters (lambda column) with its semi-axes scaled as "
        "calibrated (area scale column); primitives are ellipsoids and lines; triangles those of the drawn "
        "ellipsoids plus 2 per line.\n";
  if (std::find(result.methods.begin(), result.methods.end(), "asset") != result.methods.end())
    text +=
        "asset: the .vtree drawn by the asset renderer with its own LOD, one sample per pixel; triangles: 2 per cell "
        "drawn (mean over the views); GPU KiB: its buffers and DXT5 atlas; draw ms: its frame time; fragments not "
        "measured.\n";
  return text;
}

std::string LodBenchJson(const LodBenchResult& result) {
  nlohmann::json rows = nlohmann::json::array();
  for (const LodBenchRow& row : result.rows) {
    // Points have a lambda (the drawn share of their samples), ellipsoids a scale (of the semi-axes),
    // the asset neither.
    const bool asset = row.method == "asset";
    const auto unless = [](bool none, const nlohmann::json& value) { return none ? nlohmann::json(nullptr) : value; };
    rows.push_back({{"method", row.method},
                    {"size", row.size},
                    {"lambda", unless(asset || row.method == "ellipsoids", row.lambda)},
                    {"area_scale", unless(asset || row.method == "points", row.area_scale)},
                    {"leaves", unless(asset, row.leaves)},
                    {"triangles", row.triangles},
                    {"primitives", row.primitives},
                    {"level", row.level < 0 ? nlohmann::json(nullptr) : nlohmann::json(row.level)},
                    {"geometry_bytes", row.geometry_bytes},
                    {"texture_bytes", row.texture_bytes},
                    {"draw_ms", row.draw_ms},
                    {"fragments", row.fragments < 0 ? nlohmann::json(nullptr) : nlohmann::json(row.fragments)},
                    {"precision", row.precision},
                    {"recall", row.recall},
                    {"pr_score", row.pr_score},
                    {"multiscale_rms", row.multiscale_rms},
                    {"rgb_psnr", Number(row.rgb_psnr)},
                    {"alpha_psnr", Number(row.alpha_psnr)}});
  }
  nlohmann::json searches = nlohmann::json::array();
  for (const ScaleSearch& search : result.scale_searches) {
    nlohmann::json trials = nlohmann::json::array();
    for (const ScaleTrial& trial : search.trials)
      trials.push_back({{"area_scale", trial.area_scale}, {"precision", trial.precision}, {"recall", trial.recall}});
    searches.push_back({{"method", search.method},
                        {"size", search.size},
                        {"lambda", search.lambda},
                        {"best_area_scale", search.best.area_scale},
                        {"trials", trials}});
  }
  nlohmann::json selections = nlohmann::json::array();
  for (const LevelSelection& selection : result.level_selections) {
    nlohmann::json samples = nlohmann::json::array();
    for (const LevelSample& sample : selection.samples)
      samples.push_back({{"lambda", sample.lambda}, {"area_scale", sample.area_scale}, {"pr_score", sample.quality}});
    selections.push_back({{"size", selection.size},
                          {"cook_lambda", selection.cook_lambda},
                          {"cook_pr_score", selection.target},
                          {"lambda", selection.matched.lambda},
                          {"area_scale", selection.matched.area_scale},
                          {"samples", samples}});
  }
  nlohmann::json calibrations = nlohmann::json::array();
  for (const EllipsoidCalibration& calibration : result.ellipsoid_calibrations) {
    nlohmann::json trials = nlohmann::json::array();
    for (const auto& [scale, ms_rms] : calibration.trials)
      trials.push_back({{"scale", scale}, {"multiscale_rms", ms_rms}});
    calibrations.push_back({{"size", calibration.size},
                            {"clusters", calibration.clusters},
                            {"scale", calibration.scale},
                            {"trials", trials}});
  }
  const nlohmann::json json = {{"tree", result.tree},
                               {"renderer", result.renderer},
                               {"leaves", result.leaf_count},
                               {"triangles", result.triangle_count},
                               {"leaf_area", result.leaf_area},
                               {"views_per_size", result.views},
                               {"fragments_available", result.fragments_available},
                               {"methods", result.methods},
                               {"notes", result.notes},
                               {"rows", rows},
                               {"scale_searches", searches},
                               {"preprocess_seconds", result.preprocess_seconds},
                               {"priority_seconds", result.priority_seconds},
                               {"level_selections", selections},
                               {"level_selection_seconds", result.level_selection_seconds},
                               {"vmi_seconds", result.vmi_seconds},
                               {"skeleton_seconds", result.skeleton_seconds},
                               {"points_seconds", result.points_seconds},
                               {"ellipsoid_seconds", result.ellipsoid_seconds},
                               {"line_merge_seconds", result.line_merge_seconds},
                               {"sampled_points", result.sampled_points},
                               {"skeleton_segments", result.skeleton_segments},
                               {"ellipsoid_levels", result.ellipsoid_levels},
                               {"ellipsoid_counts", result.ellipsoid_counts},
                               {"ellipsoid_calibrations", calibrations},
                               {"ellipsoid_calibration_seconds", result.ellipsoid_calibration_seconds}};
  return json.dump(2) + "\n";
}

void WriteLodBench(const LodBenchResult& result, const std::filesystem::path& folder, Progress& progress) {
  WriteFileAtomic(folder / "table.md", LodBenchTable(result));
  WriteFileAtomic(folder / "lod_bench.json", LodBenchJson(result));
  if (!result.saved_views.empty()) {
    std::filesystem::create_directories(folder / "views");
    for (const SavedView& view : result.saved_views) WriteImage(folder / "views" / (view.name + ".png"), view.image);
  }

  std::string why_not;
  const auto gnuplot = FindGnuplot(folder / "gnuplot_probe.log", &why_not);
  std::error_code ignored;
  std::filesystem::remove(folder / "gnuplot_probe.log", ignored);
  if (!gnuplot) {
    progress.Say("lod-bench", "no plots: " + why_not);
    return;
  }
  std::map<std::string, PlotSeries> by_cost, by_fragments, by_size;
  for (const LodBenchRow& row : result.rows) {
    by_cost[row.method].title = by_fragments[row.method].title = by_size[row.method].title = row.method;
    by_cost[row.method].points.emplace_back(static_cast<double>(row.triangles), row.pr_score);
    if (row.fragments > 0) by_fragments[row.method].points.emplace_back(row.fragments / 1000.0, row.pr_score);
    by_size[row.method].points.emplace_back(row.size, row.multiscale_rms);
  }
  const auto make_spec = [](const char* file, const char* title, const char* x_label, const char* y_label) {
    PlotSpec spec;
    spec.file = file, spec.title = title, spec.x_label = x_label, spec.y_label = y_label;
    return spec;
  };
  PlotSpec cost = make_spec("quality_vs_cost.png", "PR score against triangles drawn (one point per size)",
                            "triangles drawn", "PR score Q = 1 - |(1-P, 1-R)|");
  cost.log_x = true;
  PlotSpec rms =
      make_spec("rms_vs_size.png", "Multi-scale RMS against the full mesh", "tree height (px)", "multi-scale RMS");
  rms.log_x = true;
  for (auto& [method, series] : by_cost) cost.series.push_back(series);
  for (auto& [method, series] : by_size) rms.series.push_back(series);
  // Fragments shaded: what the pixels cost, which llvmpipe's time follows more than triangles.
  PlotSpec fragments = make_spec("quality_vs_fragments.png", "PR score against fragments shaded (one point per size)",
                                 "fragments shaded per view (thousands)", "PR score Q = 1 - |(1-P, 1-R)|");
  fragments.log_x = true;
  for (auto& [method, series] : by_fragments)
    if (!series.points.empty()) fragments.series.push_back(series);

  // Neubert et al. 2011 fig. 2: one curve per lambda through the candidate scales, and the points
  // that Cook's and the PR-optimal scale choose.
  PlotSpec pr = make_spec("pr_diagram.png", "Precision-recall of pruning and scaling (input views, each size)",
                          "precision", "recall");
  PlotSeries cook{"Cook s = 1/lambda", {}}, best{"PR-optimal s", {}};
  for (const ScaleSearch& search : result.scale_searches) {
    // lambda 1: nothing to choose; the priority order's searches would double the curves.
    if (search.trials.size() < 2 || search.method != "neubert") continue;
    PlotSeries curve{Str(search.size, " px, lambda ", Fixed(search.lambda, 3)), {}};
    for (const ScaleTrial& trial : search.trials) curve.points.emplace_back(trial.precision, trial.recall);
    pr.series.push_back(curve);
    const ScaleTrial& nearest = NearestTrial(search.trials, 1 / search.lambda);
    cook.points.emplace_back(nearest.precision, nearest.recall);
    best.points.emplace_back(search.best.precision, search.best.recall);
  }
  pr.series.push_back(cook);
  pr.series.push_back(best);
  const std::filesystem::path plots = folder / "plots";
  std::filesystem::create_directories(plots);
  for (const PlotSpec& spec : {cost, fragments, rms, pr})
    if (spec.HasPoints()) DrawPlot(*gnuplot, spec, plots);
}

}  // namespace voltree
