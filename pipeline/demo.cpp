#include "pipeline/demo.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "compress/compress_workspace.h"
#include "core/contact_sheet.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "pipeline/demo_folder.h"
#include "reconstruct/reconstruct_workspace.h"
#include "samples/studio.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

constexpr const char* kSummary = "demo.json";

void WriteContactSheet(const fs::path& workspace) {
  std::vector<fs::path> photos;
  for (const auto& entry : fs::directory_iterator(workspace / "images")) photos.push_back(entry.path());
  std::sort(photos.begin(), photos.end());
  std::vector<Image8> images;
  for (const fs::path& photo : photos) images.push_back(ReadImage8(photo, 3));
  WriteImage(workspace / "report" / "contact_sheet.png", MakeContactSheet(images));
}

// The headline numbers of one view set (auto LOD), for demo.json.
nlohmann::json Headline(const MetricsReport& report) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, summary] : report.Summaries())
    out[name] = std::isfinite(summary.mean) ? nlohmann::json(summary.mean) : nlohmann::json(nullptr);
  if (!report.views.empty()) out["views"] = report.views.size();
  return out;
}

}  // namespace

OrbitFramesOptions DemoOptions::DefaultOrbit() {
  OrbitFramesOptions orbit;
  orbit.frames = 24;
  orbit.size = 512;
  return orbit;
}

CalibrateOptions DemoOptions::DefaultCalibrate() {
  CalibrateOptions calibrate;
  calibrate.max_features = 2048;
  return calibrate;
}

void DemoOptions::Check() const {
  if (output.empty()) Fail("demo: the output folder is empty");
  studio.Check();
  reconstruct.Check();
  compress.Check();
  if (orbit.frames > 0) orbit.Check();
  if (colmap) calibrate.Check();
}

DemoResult RunDemo(const DemoOptions& options, Progress& progress) {
  options.Check();
  CheckDemoOutput(options.output, options.force);  // a refusal comes before the slow work
  // Built aside; InstallDemoFolder decides what may be replaced (StagedDirectory's own check is
  // the one above, hence force here).
  StagedDirectory stage(options.output, /*force=*/true);
  const fs::path workspace = stage.path();
  nlohmann::json summary = {{"tree", TreeSourceName(options.tree)},
                            {"seed", options.tree.seed},
                            {"cameras", options.colmap ? "colmap" : "true (studio)"}};
  auto timed = [&](const char* name, auto&& work) {
    const double start = progress.ElapsedSeconds();
    work();
    summary["seconds"][name] = progress.ElapsedSeconds() - start;
  };

  timed("synth", [&] {
    std::vector<std::string> warnings;
    const TreeMesh mesh = LoadTreeMesh(options.tree, progress, &warnings);
    for (const std::string& warning : warnings) progress.Say("tree", "warning: " + warning);
    StudioOptions studio = options.studio;
    studio.tree_name = TreeSourceName(options.tree);
    PhotographTree(mesh, studio, workspace, progress, /*force=*/true);  // into the empty staging folder
    WriteContactSheet(workspace);
  });
  if (options.colmap) {
    timed("calibrate", [&] {
      // The true cameras stay as truth; COLMAP's take their place in sparse/.
      fs::rename(workspace / "sparse", workspace / "truth" / "input_sparse");
      const CalibrateReport report = CalibrateWorkspace(workspace, options.calibrate, progress);
      summary["calibration"] = {{"registered", report.registered},
                                {"images", report.images},
                                {"mean_reprojection_error_px", report.mean_reprojection_error}};
    });
  }
  timed("reconstruct", [&] { ReconstructWorkspace(workspace, {options.reconstruct}, progress); });
  CompressWorkspaceResult compressed;
  timed("compress", [&] {
    CompressWorkspaceOptions where;
    where.compress = options.compress;
    where.source_name = options.output.lexically_normal().filename().string();  // not the staging folder's
    if (where.source_name.empty())
      where.source_name = options.output.lexically_normal().parent_path().filename().string();
    compressed = CompressWorkspace(workspace, where, progress);
  });
  if (options.orbit.frames > 0)
    timed("orbit", [&] {
      const RenderJobResult orbit =
          RenderOrbitFrames(workspace / "tree.vtree", workspace / "report" / "orbit", options.orbit, progress);
      summary["orbit"] = {{"frames", orbit.frames.size()},
                          {"size", options.orbit.size},
                          {"median_ms_per_frame", orbit.median_ms},
                          {"renderer", orbit.renderer}};
    });
  DemoResult result;
  if (options.evaluate)
    timed("eval", [&] {
      EvaluateOptions evaluation = options.evaluation;
      evaluation.asset.clear();
      evaluation.report.clear();
      evaluation.workspace_label = options.output.string();
      const EvaluateResult evaluated = EvaluateWorkspace(workspace, evaluation, progress);
      summary["evaluation"] = {{"held_out", Headline(evaluated.table.Overall(ViewSet::kHeldOut))},
                               {"input", Headline(evaluated.table.Overall(ViewSet::kInput))},
                               {"render_seconds", evaluated.render_seconds},
                               {"report", "report/index.html"}};
      if (evaluated.alignment)
        summary["evaluation"]["truth_alignment"] = {
            {"mean_rotation_degrees", evaluated.alignment->mean_rotation_degrees},
            {"mean_center_error", evaluated.alignment->mean_center_error}};
      result.evaluation = evaluated.table;
      result.index_html = options.output / "report" / "index.html";
    });
  double total = 0;
  for (const auto& [stage_name, seconds] : summary["seconds"].items()) total += seconds.get<double>();
  summary["seconds"]["total"] = total;
  summary["texture_psnr_db"] = {{"vq", compressed.stats.psnr_vq}, {"dxt5", compressed.stats.psnr_dxt5}};
  summary["asset_bytes"] = fs::file_size(workspace / "tree.vtree");
  // The codebooks the byte budget kept, with the budget itself: what made the asset this size.
  nlohmann::json used = {{"reconstruct", options.reconstruct.ToJson()}, {"compress", compressed.kept.SettingsJson()}};
  used["orbit"] = {{"frames", options.orbit.frames}, {"size", options.orbit.size}};
  used["evaluate"] = options.evaluate;
  summary["options"] = used;
  WriteFileAtomic(workspace / kSummary, summary.dump(2) + "\n");
  InstallDemoFolder(workspace, options.output, options.force);
  progress.Say("demo",
               Str("done in ", std::round(total * 10) / 10, " s: ", options.output.string(), " (asset ",
                   (options.output / "tree.vtree").string(), ", ", summary["asset_bytes"].get<uint64_t>(),
                   " bytes, codebooks ", compressed.kept.colour_codebook, " / ", compressed.kept.alpha_codebook, ")"));
  result.summary = options.output / kSummary;
  result.compressed = std::move(compressed);
  result.compressed.asset = options.output / "tree.vtree";  // not the staging folder's
  result.seconds = total;
  return result;
}

}  // namespace voltree
