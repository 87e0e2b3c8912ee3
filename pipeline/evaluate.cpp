#include "pipeline/evaluate.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/files.h"
#include "core/vtree.h"
#include "pipeline/evaluation_plots.h"
#include "pipeline/evaluation_renders.h"
#include "pipeline/evaluation_report.h"
#include "pipeline/report_folder.h"
#include "pipeline/report_html.h"
#include "render/gl_context.h"
#include "render/tree_renderer.h"
#include "web/page_camera.h"
#include "web/web_page.h"

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

// The truth an evaluation compares with.
struct EvaluationTruth {
  std::optional<std::vector<TruthView>> held_out;  // none without WORKSPACE/truth
  std::vector<TruthView> inputs;                   // none when input views are off
  std::optional<TruthAlignment> alignment;         // when the held-out cameras were moved
  std::vector<std::string> notes;
};

EvaluationTruth GatherTruth(const fs::path& workspace, const EvaluateOptions& options) {
  EvaluationTruth truth;
  truth.alignment = AlignTruthToWorkspace(workspace);
  truth.held_out = HeldOutTruth(workspace);
  if (truth.held_out && truth.alignment) ApplyAlignment(*truth.alignment, &*truth.held_out);
  if (!truth.held_out)
    truth.notes.push_back(Str("no held-out truth (", (workspace / "truth").string(),
                              " does not exist): "
                              "input views only, which measures self-consistency, not generalization"));
  if (options.input_views) truth.inputs = InputTruth(workspace);
  if (!truth.held_out && truth.inputs.empty()) Fail("eval: nothing to compare: no truth/ and input views are off");
  if (options.distance != 1) {
    if (truth.held_out) truth.held_out = SeenFromFarther(std::move(*truth.held_out), options.distance);
    truth.inputs = SeenFromFarther(std::move(truth.inputs), options.distance);
    const std::vector<TruthView>& any = truth.held_out ? *truth.held_out : truth.inputs;
    truth.notes.push_back(Str("every view seen from ", options.distance, " times the cameras' distance: rendered at ",
                              any.front().camera.camera.width, "x", any.front().camera.camera.height,
                              ", the truth area-resampled to it"));
  }
  return truth;
}

// The asset as metrics.json and the page name it: relative to the workspace when inside it, so a
// staged workspace reads the same once renamed.
EvaluatedAsset DescribeAsset(const VtreeAsset& asset, const fs::path& asset_path, const fs::path& workspace) {
  const fs::path relative = asset_path.lexically_relative(workspace);
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return {inside ? relative.string() : asset_path.string(),
          fs::file_size(asset_path),
          asset.levels.size(),
          asset.CellCount(),
          asset.BillboardCount(),
          asset.colour_codebook_size,
          asset.alpha_codebook_size};
}

TreeRenderOptions AutoLod(const LodOptions& lod) {
  TreeRenderOptions options;
  options.lod = lod;
  options.lod_history = false;  // every view judged on its own, independent of the order
  return options;
}

EvaluationRenderSettings RenderSettings(const EvaluateOptions& options, const VtreeAsset& asset, fs::path staging) {
  return {LevelChoices(int(asset.levels.size()), options.each_level),
          options.metrics,
          options.lod,
          options.images,
          options.difference_gain,
          std::move(staging)};
}

// What is known before anything is rendered.
EvaluationReport StartReport(const fs::path& workspace, const EvaluateOptions& options, const EvaluationTruth& truth,
                             EvaluatedAsset asset, std::string renderer) {
  EvaluationReport report;
  report.workspace = options.workspace_label.empty() ? workspace.string() : options.workspace_label;
  report.asset = std::move(asset);
  report.renderer = std::move(renderer);
  report.metrics = options.metrics;
  report.lod = options.lod;
  report.difference_gain = options.difference_gain;
  report.held_out_views = truth.held_out ? truth.held_out->size() : 0;
  report.input_views = truth.inputs.size();
  report.alignment = truth.alignment;
  report.notes = options.notes;
  report.notes.insert(report.notes.end(), truth.notes.begin(), truth.notes.end());
  return report;
}

fs::path OrDefault(const fs::path& path, const fs::path& fallback) { return path.empty() ? fallback : path; }

// The plots drawn into the staged eval/plots/, relative to the report folder, and notes on those
// that were not.
DrawnPlots ReportPlots(const EvaluateOptions& options, const EvaluationReport& report, const fs::path& folder,
                       const fs::path& staging) {
  if (!options.plots) return {{}, {"plots not drawn (turned off)"}};
  DrawnPlots plots = DrawPlots(EvaluationPlotSpecs(report.table, report.pruning,
                                                   OrDefault(options.codebook_sweep, folder / "codebook_sweep.json"),
                                                   OrDefault(options.scene_bench, folder / "scene_bench.json")),
                               staging / "plots");
  for (std::string& file : plots.files) file = Str(kEvalFolderName, "/plots/", file);
  return plots;
}

EvaluateResult ResultOf(EvaluationReport report, const fs::path& folder, double render_seconds) {
  EvaluateResult result;
  result.table = std::move(report.table);
  result.budget = std::move(report.budget);
  result.alignment = report.alignment;
  result.metrics_json = folder / kMetricsJsonName;
  result.index_html = folder / kIndexHtmlName;
  result.plots = std::move(report.plots);
  result.notes = std::move(report.notes);
  result.renderer = std::move(report.renderer);
  result.render_seconds = render_seconds;
  return result;
}

// Frames the web page (REPORT/eval/web/) at each held-out camera, as eval renders: over its grey,
// each view's levels chosen on its own (no LOD history).
void LinkWebPage(const std::vector<TruthView>& held_out, double grey, std::vector<ComparisonFiles>* comparisons) {
  const int level = int(std::lround(grey));
  for (size_t v = 0; v < comparisons->size() && v < held_out.size(); ++v) {
    const View& camera = held_out[v].camera;
    const std::optional<std::string> parameter = PageCameraParameter(camera);
    if (!parameter) continue;  // a camera the page cannot take (distortion): no frame
    ComparisonFiles& files = (*comparisons)[v];
    files.interactive = Str(kEvalFolderName, "/", kWebFolderName, "/index.html?ui=0&history=0&background=", level, ",",
                            level, ",", level, "&", *parameter);
    files.interactive_height = int(std::lround(256.0 * camera.camera.height / camera.camera.width));
  }
}

}  // namespace

fs::path EvaluateOptions::AssetPath(const fs::path& workspace) const {
  return asset.empty() ? workspace / "tree.vtree" : asset;
}
fs::path EvaluateOptions::ReportPath(const fs::path& workspace) const {
  return report.empty() ? workspace / "report" : report;
}

void EvaluateOptions::Check() const {
  metrics.Check();
  lod.Check();
  if (lod.forced_level >= 0)
    Fail("eval: lod.forced_level = ", lod.forced_level, "; per-level renders are chosen by each_level");
  if (!(difference_gain > 0)) Fail("eval: difference_gain = ", difference_gain, ", expected > 0");
  if (!(distance >= 1 && distance <= 64)) FailOption("EvaluateOptions.distance", "must be in [1, 64], got ", distance);
  if (budget && distance != 1)
    FailOption("EvaluateOptions.distance", "the error budget (--budget) is measured at the photos' own size; got ",
               distance);
}

EvaluateResult EvaluateWorkspace(const fs::path& workspace, const EvaluateOptions& options, Progress& progress) {
  if (workspace.empty()) Fail("eval: the workspace folder is empty");
  if (!fs::is_directory(workspace)) Fail(workspace.string(), ": no such workspace folder");
  options.Check();
  const double start = progress.ElapsedSeconds();
  const fs::path folder = options.ReportPath(workspace), asset_path = options.AssetPath(workspace);
  // Refuse at once, before any slow work.
  CheckCanWriteReport(folder, options.force);
  if (!fs::exists(asset_path))
    Fail(asset_path.string(), ": no asset (run 'voltree compress ", workspace.string(), "' first, or pass --asset)");

  const EvaluationTruth truth = GatherTruth(workspace, options);
  const std::vector<TruthView> held_out = truth.held_out.value_or(std::vector<TruthView>{});
  const VtreeAsset asset = ReadAsset(asset_path);
  GlContext context;
  TreeRenderer renderer(asset);
  EvaluationReport report =
      StartReport(workspace, options, truth, DescribeAsset(asset, asset_path, workspace), context.renderer());

  CreatedFolder report_folder(folder);
  StagedDirectory staged(folder / kEvalFolderName, /*force=*/true);  // ownership checked above
  WriteFileAtomic(staged.path() / kEvalMarkerName, Str("written by ", kEvalGenerator, "; replaced on every run\n"));
  fs::create_directories(staged.path() / "held_out");
  const EvaluationRenderSettings settings = RenderSettings(options, asset, staged.path());
  progress.Say("eval", Str(asset_path.string(), ": ", asset.levels.size(), " levels; ", held_out.size(),
                           " held-out and ", truth.inputs.size(), " input views x ", settings.choices.size(),
                           " level settings on ", report.renderer));
  EvaluationRenders renders = RenderAndCompare(held_out, truth.inputs, settings, renderer, progress);
  report.table = std::move(renders.table);
  report.comparisons = std::move(renders.comparisons);
  if (options.budget) {
    const LodRenderer render_lod = [&](const View& camera) { return renderer.Render(camera, AutoLod(options.lod)); };
    report.budget = MeasureErrorBudget(workspace, asset, held_out, truth.inputs, options.metrics, render_lod, progress);
  }
  report.pruning = ReadPruningStats(workspace, asset, asset_path);
  DrawnPlots plots = ReportPlots(options, report, folder, staged.path());
  report.plots = std::move(plots.files);
  report.notes.insert(report.notes.end(), plots.notes.begin(), plots.notes.end());
  if (options.images && truth.held_out) {  // the asset in the web page, framed beside each truth
    WebPageOptions page;
    page.input = asset_path;
    page.output = staged.path() / kWebFolderName;
    WriteWebPage(page);
    LinkWebPage(held_out, options.metrics.background_grey, &report.comparisons);
  }
  staged.Commit();
  report_folder.Keep();

  WriteFileAtomic(folder / kMetricsJsonName, MetricsJson(report).dump(2) + "\n");
  WriteFileAtomic(folder / kIndexHtmlName, ReportHtml(EvaluationPage(report, OrbitThumbnails(folder, 12),
                                                                     fs::exists(folder / "contact_sheet.png"))));
  EvaluateResult result = ResultOf(std::move(report), folder, renders.render_seconds);
  result.seconds = progress.ElapsedSeconds() - start;
  progress.Say("eval", Str("wrote ", result.index_html.string(), " (rendering ",
                           std::round(result.render_seconds * 10) / 10, " s)"));
  return result;
}

}  // namespace voltree
