#include "pipeline/run_workspace.h"

#include <cmath>

#include "compress/compress_workspace.h"
#include "core/error.h"
#include "core/files.h"
#include "pipeline/report_folder.h"
#include "pipeline/stage_record.h"
#include "reconstruct/workspace.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

bool NeedsMattes(const fs::path& dir) { return !fs::is_directory(dir / "mattes"); }
bool NeedsCameras(const fs::path& dir) { return !fs::is_directory(dir / "sparse"); }

// What the resumable stages are made from (pipeline/stage_record.h): a stage whose record still
// matches is skipped, unless --force.
constexpr const char* kUpToDate = "up to date: inputs and options unchanged since it ran";
StageRecipe ReconstructRecipe(const RunOptions& options) {
  return {"reconstruct", {"images", "mattes", "foreground", "sparse", "scene.json"}, {"volume"},
          options.reconstruct.ToJson().dump()};
}
StageRecipe CompressRecipe(const RunOptions& options) {
  return {"compress", {"volume"}, {"tree.vtree"}, options.compress.ToJson().dump()};
}
StageRecipe OrbitRecipe(const RunOptions& options) {
  // Recipes name paths inside the workspace; a report elsewhere is named absolutely.
  const fs::path orbit = options.evaluate.report.empty() ? fs::path("report") / "orbit"
                                                         : fs::absolute(options.evaluate.report / "orbit");
  return {"orbit", {"tree.vtree"}, {orbit.string()}, Str(options.orbit.frames, " ", options.orbit.size)};
}

}  // namespace

void RunOptions::Check() const {
  if (workspace.empty()) Fail("run: the workspace folder is empty");
  matte.Check();
  calibrate.Check();
  reconstruct.Check();
  compress.Check();
  orbit.Check();
}

void CheckRunWorkspace(const RunOptions& options) {
  options.Check();
  const fs::path& dir = options.workspace;
  if (!fs::is_directory(dir)) Fail(dir.string(), ": no such workspace folder");
  if (NeedsMattes(dir) || NeedsCameras(dir)) {
    const fs::path images = dir / "images";
    const std::string why = NeedsMattes(dir) && NeedsCameras(dir) ? "mattes/ and sparse/ are missing"
                            : NeedsMattes(dir)                   ? "mattes/ is missing"
                                                                 : "sparse/ is missing";
    if (!fs::is_directory(images))
      Fail(images.string(), ": missing; ", why, ", so the photos of the tree are needed (PNG, JPEG, TIFF or BMP)");
    if (ListImages(images).empty()) Fail(images.string(), ": no photos (png, jpg, tif, bmp); ", why);
  }
  if (!NeedsMattes(dir) && !NeedsCameras(dir) && !fs::is_directory(dir / "images") &&
      !fs::is_directory(dir / "foreground"))
    Fail(dir.string(), ": neither images/ nor foreground/: reconstruct needs the colours of the photos");
  if (NeedsMattes(dir) && fs::exists(dir / "foreground") && !options.force)
    Fail((dir / "foreground").string(), ": exists but mattes/ does not; pass --force to compute both again");
  const fs::path report = options.evaluate.report.empty() ? dir / "report" : options.evaluate.report;
  // Outputs that an earlier run wrote (and nobody changed since) may be replaced: resuming.
  CheckCanReplaceFolder(dir / "volume", options.force || StageOwnsOutputs(dir, ReconstructRecipe(options)));
  CheckCanWrite(dir / "tree.vtree", options.force || StageOwnsOutputs(dir, CompressRecipe(options)));
  CheckCanReplaceFolder(report / "orbit", options.force || StageOwnsOutputs(dir, OrbitRecipe(options)));
  CheckCanWriteReport(report, options.force || options.evaluate.force);
}

RunResult RunWorkspace(const RunOptions& options, Progress& progress) {
  CheckRunWorkspace(options);
  const fs::path& dir = options.workspace;
  RunResult result;
  auto stage = [&](const char* name, bool needed, const std::string& skipped, auto&& work) {
    if (!needed) {
      result.stages.push_back({name, 0, skipped});
      progress.Say(name, "skipped: " + skipped);
      return;
    }
    const double start = progress.ElapsedSeconds();
    progress.Say(name, "start");
    work();
    const double seconds = progress.ElapsedSeconds() - start;
    result.stages.push_back({name, seconds, "ran"});
    progress.Say(name, Str("done in ", std::round(seconds * 10) / 10, " s"));
  };

  stage("matte", NeedsMattes(dir), "mattes/ exists", [&] {
    MatteWorkspaceOptions matte = options.matte;
    matte.force = matte.force || options.force;
    MatteWorkspace(dir, matte, progress);
  });
  stage("calibrate", NeedsCameras(dir), "sparse/ exists", [&] {
    CalibrateOptions calibrate = options.calibrate;
    calibrate.force = calibrate.force || options.force;
    const CalibrateReport report = Calibrate(dir, calibrate, progress);
    progress.Say("calibrate", Str(report.registered, "/", report.images, " photos registered, mean reprojection error ",
                                  report.mean_reprojection_error, " px"));
  });
  // A resumable stage runs when --force or when its record does not match; the record is dropped
  // before it runs and written once it finished.
  // before it runs and written once it finished. `replace`: its outputs may be replaced.
  auto resumable = [&](const StageRecipe& recipe, auto&& work) {
    stage(recipe.stage.c_str(), options.force || !StageIsUpToDate(dir, recipe), kUpToDate, [&] {
      const bool replace = options.force || StageOwnsOutputs(dir, recipe);
      ForgetStage(dir, recipe);
      work(replace);
      RecordStage(dir, recipe);
    });
  };
  resumable(ReconstructRecipe(options),
            [&](bool replace) { ReconstructWorkspace(dir, options.reconstruct, replace, &progress); });
  result.asset = dir / "tree.vtree";
  resumable(CompressRecipe(options), [&](bool replace) {
    CompressWorkspaceOptions workspace_options;
    workspace_options.force = replace;
    result.asset = CompressWorkspace(dir, options.compress, workspace_options, &progress);
  });
  const fs::path report = options.evaluate.report.empty() ? dir / "report" : options.evaluate.report;
  resumable(OrbitRecipe(options), [&](bool replace) {
    OrbitFramesOptions orbit = options.orbit;
    orbit.force = orbit.force || replace;
    fs::create_directories(report);
    RenderOrbitFrames(result.asset, report / "orbit", orbit, progress);
  });
  stage("eval", true, "", [&] {
    EvaluateOptions evaluate = options.evaluate;
    evaluate.workspace = dir;
    evaluate.asset = result.asset;
    evaluate.report = report;
    evaluate.force = evaluate.force || options.force;
    result.evaluation = EvaluateWorkspace(evaluate, progress);
  });
  return result;
}

}  // namespace voltree
