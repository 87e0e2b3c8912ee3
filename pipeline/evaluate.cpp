#include "pipeline/evaluate.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "pipeline/comparison_images.h"
#include "pipeline/measured_series.h"
#include "pipeline/plots.h"
#include "pipeline/report_folder.h"
#include "pipeline/report_html.h"
#include "web/page_camera.h"
#include "web/web_page.h"
#include "render/gl_context.h"
#include "render/tree_renderer.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// A report folder that eval had to create is removed again if eval fails before filling it, so
// a failed run leaves no empty report/ behind.
class CreatedFolder {
 public:
  explicit CreatedFolder(const fs::path& path) : path_(path), created_(fs::create_directories(path)) {}
  ~CreatedFolder() {
    std::error_code ignored;
    if (created_ && !kept_ && fs::is_empty(path_, ignored)) fs::remove(path_, ignored);
  }
  void Keep() { kept_ = true; }

 private:
  fs::path path_;
  bool created_ = false, kept_ = false;
};

// held_out/a/b.png -> "a_b": report file names are flat.
std::string FlatStem(const std::string& view_name) {
  std::string stem = fs::path(view_name).replace_extension().string();
  std::replace(stem.begin(), stem.end(), '/', '_');
  return stem;
}

nlohmann::json Finite(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

// One view's metrics at every level choice, filled by worker threads.
struct ViewResults {
  std::vector<ViewMetrics> per_choice;
};

struct ComparisonFiles {
  std::string truth, render, difference;  // relative to the report folder
};

// Renders one view at every level choice on the GL thread; the comparisons (and the report's
// images for the auto LOD) run on worker threads of `compare` while the next view renders.
void EvaluateView(const TruthView& view, ViewSet set, const std::vector<LevelChoice>& choices,
                  const EvaluateOptions& options, TreeRenderer& renderer, const fs::path& staging,
                  tbb::task_group& compare, ViewResults* results, ComparisonFiles* files, double* render_seconds,
                  Progress& progress) {
  auto truth = std::make_shared<const Image8>(LoadTruthImage(view));
  ImageMetricsOptions metrics = options.metrics;
  metrics.truth_premultiplied = view.premultiplied;
  metrics.render_premultiplied = false;  // TreeRenderer::Render returns straight alpha
  results->per_choice.resize(choices.size());
  for (size_t c = 0; c < choices.size(); ++c) {
    TreeRenderOptions render_options;
    render_options.lod = options.lod;
    render_options.lod.forced_level = choices[c].forced_level;
    render_options.lod_history = false;  // every view judged on its own, independent of the order
    const double start = progress.ElapsedSeconds();
    auto render = std::make_shared<const Image8>(renderer.Render(view.camera, render_options));
    *render_seconds += progress.ElapsedSeconds() - start;
    const bool write_images = options.images && set == ViewSet::kHeldOut && choices[c].IsAuto();
    if (write_images) {
      const std::string stem = Str(kEvalFolderName, "/held_out/", FlatStem(view.camera.name));
      *files = {stem + "_truth.png", stem + "_voltree.png", stem + "_difference.png"};
    }
    compare.run([=, &options, out = &results->per_choice[c]] {
      *out = CompareViews(*render, *truth, metrics);
      if (!write_images) return;
      const Image8 truth_rgb = CompositeForDisplay(*truth, metrics.background_grey, metrics.truth_premultiplied);
      const Image8 render_rgb = CompositeForDisplay(*render, metrics.background_grey, false);
      const fs::path folder = staging / "held_out";
      const std::string stem = FlatStem(view.camera.name);
      WriteImage(folder / (stem + "_truth.png"), truth_rgb);
      WriteImage(folder / (stem + "_voltree.png"), render_rgb);
      WriteImage(folder / (stem + "_difference.png"), AmplifiedDifference(truth_rgb, render_rgb, options.difference_gain));
    });
  }
}

PlotSpec MakePlot(std::string file, std::string title, std::string x_label, std::string y_label) {
  PlotSpec spec;
  spec.file = std::move(file), spec.title = std::move(title);
  spec.x_label = std::move(x_label), spec.y_label = std::move(y_label);
  return spec;
}

std::vector<PlotSpec> PlotSpecs(const LevelMetricsTable& table, const PruningStats& pruning,
                                const EvaluateOptions& options, const fs::path& report) {
  std::vector<PlotSpec> specs;
  PlotSpec pruned = MakePlot("pruned_per_level.png", "Billboards pruned per level (reconstruct)", "octree level", "pruned %");
  pruned.style = PlotStyle::kBars, pruned.integer_x = true;
  PlotSeries pruned_series{"pruned %", {}};
  for (const LevelPruning& level : pruning.levels) pruned_series.points.emplace_back(level.level, level.pruned_percent);
  pruned.series.push_back(pruned_series);
  specs.push_back(pruned);

  PlotSpec psnr = MakePlot("psnr_per_level.png", "RGB PSNR per forced level (over grey)", "octree level", "RGB PSNR (dB)");
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

  const fs::path sweep = options.codebook_sweep.empty() ? report / "codebook_sweep.json" : options.codebook_sweep;
  PlotSpec codebook = MakePlot("psnr_vs_codebook.png", "PSNR vs colour codebook size", "colour codebook size", "PSNR (dB)");
  codebook.log_x = true;
  codebook.series = ReadSeriesFile(sweep, {"codebook", "colour_codebook", "codebook_size"},
                                   {"rgb_psnr", "psnr", "psnr_db"}, "PSNR");
  specs.push_back(codebook);

  const fs::path bench = options.scene_bench.empty() ? report / "scene_bench.json" : options.scene_bench;
  PlotSpec scene = MakePlot("ms_per_frame_vs_trees.png", "Frame time vs trees in the scene", "trees", "ms per frame (median)");
  scene.series = ReadSeriesFile(bench, {"trees", "instances"}, {"median_ms", "ms_per_frame"}, "median ms");
  specs.push_back(scene);
  return specs;
}

// Draws the plots that have data into `folder`; notes say which were skipped and why.
std::vector<std::string> DrawPlots(const std::vector<PlotSpec>& specs, const fs::path& folder,
                                   std::vector<std::string>* notes) {
  std::vector<std::string> drawn;
  fs::create_directories(folder);
  std::string why_not;
  const fs::path probe_log = folder / "gnuplot_probe.log";
  const std::optional<Gnuplot> gnuplot = FindGnuplot(probe_log, &why_not);
  std::error_code ignored;
  fs::remove(probe_log, ignored);
  if (!gnuplot) {
    notes->push_back("plots skipped: " + why_not);
    return drawn;
  }
  for (const PlotSpec& spec : specs) {
    if (!spec.HasPoints()) continue;  // only measured data is plotted
    try {
      DrawPlot(*gnuplot, spec, folder);
      drawn.push_back(spec.file);
    } catch (const Error& error) {
      notes->push_back(Str("plot ", spec.file, " skipped: ", error.what()));
    }
  }
  return drawn;
}

nlohmann::json AlignmentJson(const std::optional<TruthAlignment>& alignment) {
  if (!alignment) return nullptr;
  const Similarity& s = alignment->truth_to_workspace;
  return {{"from", "truth/input_sparse"},
          {"to", "sparse"},
          {"scale", s.scale},
          {"rotation_wxyz", {s.rotation.w(), s.rotation.x(), s.rotation.y(), s.rotation.z()}},
          {"translation", {s.translation.x(), s.translation.y(), s.translation.z()}},
          {"matched_views", alignment->matched_views},
          {"mean_rotation_degrees", alignment->mean_rotation_degrees},
          {"mean_center_error", alignment->mean_center_error}};
}

// Up to `count` orbit frames spread evenly over REPORT/orbit/, relative to the report.
std::vector<std::string> OrbitThumbnails(const fs::path& report, size_t count) {
  std::vector<std::string> frames;
  if (!fs::is_directory(report / "orbit")) return frames;
  for (const auto& entry : fs::directory_iterator(report / "orbit"))
    if (entry.path().extension() == ".png") frames.push_back("orbit/" + entry.path().filename().string());
  std::sort(frames.begin(), frames.end());
  if (frames.size() <= count) return frames;
  std::vector<std::string> picked;
  for (size_t i = 0; i < count; ++i) picked.push_back(frames[i * frames.size() / count]);
  return picked;
}

}  // namespace

fs::path EvaluateOptions::AssetPath() const { return asset.empty() ? workspace / "tree.vtree" : asset; }
fs::path EvaluateOptions::ReportPath() const { return report.empty() ? workspace / "report" : report; }

void EvaluateOptions::Check() const {
  if (workspace.empty()) Fail("eval: the workspace folder is empty");
  if (!fs::is_directory(workspace)) Fail(workspace.string(), ": no such workspace folder");
  metrics.Check();
  lod.Check();
  if (lod.forced_level >= 0) Fail("eval: lod.forced_level = ", lod.forced_level, "; per-level renders are chosen by each_level");
  if (!(difference_gain > 0)) Fail("eval: difference_gain = ", difference_gain, ", expected > 0");
}

EvaluateResult EvaluateWorkspace(const EvaluateOptions& options, Progress& progress) {
  options.Check();
  const double start = progress.ElapsedSeconds();
  const fs::path report = options.ReportPath(), asset_path = options.AssetPath(), workspace = options.workspace;
  // Refuse at once, before any slow work.
  CheckCanWriteReport(report, options.force);
  if (!fs::exists(asset_path))
    Fail(asset_path.string(), ": no asset (run 'voltree compress ", workspace.string(), "' first, or pass --asset)");

  EvaluateResult result;
  result.notes = options.notes;
  result.alignment = AlignTruthToWorkspace(workspace);
  std::optional<std::vector<TruthView>> held_out = HeldOutTruth(workspace);
  if (held_out && result.alignment) ApplyAlignment(*result.alignment, &*held_out);
  if (!held_out) result.notes.push_back(Str("no held-out truth (", (workspace / "truth").string(), " does not exist): "
                                            "input views only, which measures self-consistency, not generalization"));
  const std::vector<TruthView> inputs = options.input_views ? InputTruth(workspace) : std::vector<TruthView>{};
  if (!held_out && inputs.empty()) Fail("eval: nothing to compare: no truth/ and input views are off");

  const VtreeAsset asset = ReadAsset(asset_path);
  GlContext context;
  TreeRenderer renderer(asset);
  result.renderer = context.renderer();
  const std::vector<LevelChoice> choices = LevelChoices(int(asset.levels.size()), options.each_level);
  progress.Say("eval", Str(asset_path.string(), ": ", asset.levels.size(), " levels; ", held_out ? held_out->size() : 0,
                           " held-out and ", inputs.size(), " input views x ", choices.size(), " level settings on ",
                           result.renderer));

  CreatedFolder report_folder(report);
  StagedDirectory staged(report / kEvalFolderName, /*force=*/true);  // ownership checked above
  WriteFileAtomic(staged.path() / kEvalMarkerName, Str("written by ", kEvalGenerator, "; replaced on every run\n"));
  fs::create_directories(staged.path() / "held_out");

  const std::vector<TruthView> no_views;
  const std::array<std::pair<ViewSet, const std::vector<TruthView>*>, 2> sets = {
      std::pair{ViewSet::kHeldOut, held_out ? &*held_out : &no_views}, std::pair{ViewSet::kInput, &inputs}};
  std::array<std::vector<ViewResults>, 2> results;
  std::vector<ComparisonFiles> files(held_out ? held_out->size() : 0);
  {
    // Two groups in turn: a view's comparisons overlap the next view's renders, and at most two
    // views' images are in memory at once.
    std::array<tbb::task_group, 2> compare;
    size_t turn = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
      const auto& [set, views] = sets[s];
      results[s].resize(views->size());
      for (size_t v = 0; v < views->size(); ++v, ++turn) {
        compare[turn % 2].wait();
        EvaluateView((*views)[v], set, choices, options, renderer, staged.path(), compare[turn % 2], &results[s][v],
                     set == ViewSet::kHeldOut ? &files[v] : nullptr, &result.render_seconds, progress);
        progress.Say("eval", Str(ViewSetName(set), " ", (*views)[v].camera.name, " ", v + 1, "/", views->size()));
      }
    }
    compare[0].wait();
    compare[1].wait();
  }
  result.table = LevelMetricsTable(choices);
  for (size_t s = 0; s < sets.size(); ++s)
    for (size_t v = 0; v < results[s].size(); ++v)
      for (size_t c = 0; c < choices.size(); ++c)
        result.table.Add(choices[c], sets[s].first, (*sets[s].second)[v].camera.name, results[s][v].per_choice[c]);

  if (options.budget) {
    const LodRenderer render_lod = [&](const View& camera) {
      TreeRenderOptions render_options;
      render_options.lod = options.lod;
      render_options.lod_history = false;
      return renderer.Render(camera, render_options);
    };
    result.budget = MeasureErrorBudget(workspace, asset, held_out ? *held_out : no_views, inputs, options.metrics,
                                       render_lod, progress);
  }
  const PruningStats pruning = ReadPruningStats(workspace, asset, asset_path);
  if (options.plots) {
    for (const std::string& file : DrawPlots(PlotSpecs(result.table, pruning, options, report),
                                             staged.path() / "plots", &result.notes))
      result.plots.push_back(Str(kEvalFolderName, "/plots/", file));
  } else {
    result.notes.push_back("plots not drawn (turned off)");
  }
  // The asset in the web page, one frame per held-out view at its camera (report_html.h).
  if (options.images && held_out) {
    WebPageOptions web;
    web.input = asset_path;
    web.output = staged.path() / kWebFolderName;
    WriteWebPage(web);
  }
  staged.Commit();
  report_folder.Keep();

  // metrics.json: deterministic for a given asset and renderer (no timings). Paths inside the
  // workspace are written relative to it, so a staged workspace reads the same once renamed.
  const std::string label = options.workspace_label.empty() ? workspace.string() : options.workspace_label;
  const fs::path relative_asset = asset_path.lexically_relative(workspace);
  const std::string asset_name = !relative_asset.empty() && *relative_asset.begin() != ".."
                                     ? relative_asset.string()
                                     : asset_path.string();
  nlohmann::json doc = result.table.ToJson();
  doc["generator"] = kEvalGenerator;
  doc["format_version"] = 1;
  doc["workspace"] = label;
  doc["asset"] = asset_name;
  doc["renderer"] = result.renderer;
  doc["settings"] = {{"background_grey", options.metrics.background_grey},
                     {"coverage_threshold", options.metrics.coverage_threshold},
                     {"ssim_window", options.metrics.ssim_window},
                     {"ssim_sigma", options.metrics.ssim_sigma},
                     {"lod_rule", LodRuleName(options.lod.rule)},
                     {"max_texel_pixels", options.lod.max_texel_pixels},
                     {"lod_history", false},
                     {"levels", asset.levels.size()}};
  doc["view_counts"] = {{"held_out", held_out ? held_out->size() : 0}, {"input", inputs.size()}};
  doc["truth_alignment"] = AlignmentJson(result.alignment);
  if (!result.budget.empty()) {
    nlohmann::json budget = nlohmann::json::array();
    for (const BudgetRow& row : result.budget)
      budget.push_back({{"step", row.step}, {"views", ViewSetName(row.set)}, {"count", row.views},
                        {"rgb_psnr", Finite(row.rgb_psnr)}, {"alpha_psnr", Finite(row.alpha_psnr)},
                        {"precision", row.precision}, {"recall", row.recall},
                        {"bark_recall", Finite(row.bark_recall)}, {"leaf_recall", Finite(row.leaf_recall)}});
    doc["budget"] = budget;
  }
  nlohmann::json pruning_json = nlohmann::json::array();
  for (const LevelPruning& level : pruning.levels)
    pruning_json.push_back({{"level", level.level},
                            {"billboards_before_pruning", level.billboards_before_pruning},
                            {"billboards", level.billboards},
                            {"pruned_percent", Finite(level.pruned_percent)}});
  doc["pruning"] = {{"source", pruning.source}, {"levels", pruning_json}};
  doc["asset_stats"] = {{"bytes", fs::file_size(asset_path)},
                        {"cells", asset.CellCount()},
                        {"billboards", asset.BillboardCount()},
                        {"colour_codebook", asset.colour_codebook_size},
                        {"alpha_codebook", asset.alpha_codebook_size}};
  nlohmann::json images = nlohmann::json::array();
  for (size_t v = 0; v < files.size() && options.images; ++v)
    images.push_back({{"view", (*held_out)[v].camera.name},
                      {"truth", files[v].truth},
                      {"render", files[v].render},
                      {"difference", files[v].difference}});
  doc["images"] = images;
  doc["plots"] = result.plots;
  doc["notes"] = result.notes;
  result.metrics_json = report / kMetricsJsonName;
  WriteFileAtomic(result.metrics_json, doc.dump(2) + "\n");

  ReportPage page;
  page.title = Str("voltree evaluation: ", label);
  page.facts = {{"workspace", label},
                {"asset", Str(asset_name, " (", fs::file_size(asset_path), " bytes, ", asset.levels.size(),
                              " levels, ", asset.BillboardCount(), " billboards, codebooks ", asset.colour_codebook_size,
                              " colour / ", asset.alpha_codebook_size, " alpha)")},
                {"renderer", result.renderer},
                {"background", Str("grey ", options.metrics.background_grey, " (8-bit), LOD rule ",
                                   LodRuleName(options.lod.rule), ", ", options.lod.max_texel_pixels, " px per texel")}};
  if (result.alignment)
    page.facts.push_back({"truth alignment", Str("held-out cameras moved into the calibrated frame by a similarity fit to ",
                                                 result.alignment->matched_views, " input cameras; residual ",
                                                 result.alignment->mean_rotation_degrees, " deg, centre error ",
                                                 result.alignment->mean_center_error, " of the camera distance")});
  page.notes = result.notes;
  page.table = &result.table;
  for (const LevelPruning& level : pruning.levels) page.pruned_percent[level.level] = level.pruned_percent;
  for (size_t v = 0; v < files.size() && options.images; ++v) {
    const View& camera = (*held_out)[v].camera;
    HtmlComparison comparison;
    comparison.view = camera.name;
    comparison.truth = files[v].truth, comparison.render = files[v].render, comparison.difference = files[v].difference;
    comparison.metrics = result.table.Overall(ViewSet::kHeldOut).views[v].metrics;
    // As eval renders: over its grey, each view's levels chosen on its own (no LOD history).
    if (const auto parameter = PageCameraParameter(camera)) {
      comparison.interactive = Str(kEvalFolderName, "/", kWebFolderName, "/index.html?ui=0&history=0&background=",
                                   int(std::lround(options.metrics.background_grey)), ",",
                                   int(std::lround(options.metrics.background_grey)), ",",
                                   int(std::lround(options.metrics.background_grey)), "&", *parameter);
      comparison.interactive_height = int(std::lround(256.0 * camera.camera.height / camera.camera.width));
    }
    page.comparisons.push_back(comparison);
  }
  page.difference_gain = options.difference_gain;
  for (const std::string& plot : result.plots) page.plots.push_back({plot, fs::path(plot).stem().string()});
  page.thumbnails = OrbitThumbnails(report, 12);
  page.budget = result.budget;
  page.links.push_back({kMetricsJsonName, "metrics.json (every view, every level)"});
  if (fs::exists(report / "contact_sheet.png")) page.links.push_back({"contact_sheet.png", "contact sheet of the input photos"});
  if (!page.thumbnails.empty()) page.links.push_back({"orbit/", "orbit frames"});
  result.index_html = report / kIndexHtmlName;
  WriteFileAtomic(result.index_html, ReportHtml(page));
  result.seconds = progress.ElapsedSeconds() - start;
  progress.Say("eval", Str("wrote ", result.index_html.string(), " (rendering ", std::round(result.render_seconds * 10) / 10, " s)"));
  return result;
}

}  // namespace voltree
