#include "pipeline/run_workspace.h"

#include <cmath>

#include "capture/colmap_binary.h"
#include "capture/photo_folder.h"
#include "compress/compress_workspace.h"
#include "core/colmap_model.h"
#include "core/image.h"
#include "core/error.h"
#include "core/files.h"
#include "pipeline/report_folder.h"
#include "pipeline/stage_record.h"
#include "reconstruct/reconstruct_workspace.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

bool NeedsMattes(const fs::path& dir) { return !fs::is_directory(dir / "mattes"); }
bool NeedsCameras(const fs::path& dir) { return !fs::is_directory(dir / "sparse"); }

// What the resumable stages are made from (pipeline/stage_record.h): a stage whose record still
// matches is skipped, unless --force.
constexpr const char* kUpToDate = "up to date: inputs and options unchanged since it ran";
StageRecipe ReconstructRecipe(const RunOptions& options) {
  return {"reconstruct",
          {"images", "mattes", "foreground", "sparse", "scene.json"},
          {"volume"},
          options.reconstruct.ToJson().dump()};
}
StageRecipe CompressRecipe(const RunOptions& options) {
  return {"compress", {"volume"}, {"tree.vtree"}, options.compress.SettingsJson().dump()};
}
StageRecipe OrbitRecipe(const RunOptions& options) {
  // Recipes name paths inside the workspace; a report elsewhere is named absolutely.
  const fs::path orbit =
      options.evaluate.report.empty() ? fs::path("report") / "orbit" : fs::absolute(options.evaluate.report / "orbit");
  return {"orbit", {"tree.vtree"}, {orbit.string()}, Str(options.orbit.frames, " ", options.orbit.size)};
}

// The registered views (sparse/) and their mattes, in the same order.
std::pair<std::vector<View>, std::vector<Image8>> LoadViewsAndMattes(const fs::path& dir) {
  std::pair<std::vector<View>, std::vector<Image8>> loaded;
  loaded.first = ReadColmapModel(dir / "sparse").Views();
  for (const View& view : loaded.first) {
    const fs::path matte = CompanionPath(dir, "mattes", view.name);
    if (!fs::is_regular_file(matte))
      Fail(matte.string(), ": missing matte for image '", view.name, "' (delete mattes/ to compute them all)");
    loaded.second.push_back(ReadImage8(matte, 1));
  }
  return loaded;
}

// Each matte covers a plausible part of its photo; throws Error naming those that do not.
void CheckMatteCoverages(const fs::path& dir, const std::vector<View>& views, const std::vector<Image8>& mattes,
                         const RunOptions& options) {
  std::vector<NamedCoverage> coverages;
  for (size_t i = 0; i < views.size(); ++i) coverages.push_back({views[i].name, MatteCoverage(mattes[i])});
  CheckMatteCoverage(coverages, options.matte.coverage, Str("in ", (dir / "mattes").string()), false);
}

// The mattes before any reconstruction: each covers a plausible part of its photo, and all of
// them agree through the cameras.
void CheckMattes(const fs::path& dir, const RunOptions& options, Progress& progress) {
  const auto [views, mattes] = LoadViewsAndMattes(dir);
  CheckMatteCoverages(dir, views, mattes, options);
  if (int(views.size()) < options.consistency.min_photos) {
    progress.Say("check", Str("only ", views.size(),
                              " photos: their visual hull is too loose to check the mattes "
                              "against each other (needs ",
                              options.consistency.min_photos, ")"));
    return;
  }
  const MatteConsistency consistency = MeasureMatteConsistency(views, mattes, options.consistency);
  double worst_recall = 1, worst_precision = 1;
  for (const PhotoConsistency& photo : consistency.photos) {
    worst_recall = std::min(worst_recall, photo.recall);
    worst_precision = std::min(worst_precision, photo.precision);
  }
  progress.Say("check", Str("mattes against the cameras (visual hull of ", consistency.hull_voxels,
                            " voxels): worst recall ", std::round(worst_recall * 1000) / 1000, ", worst precision ",
                            std::round(worst_precision * 1000) / 1000));
  CheckMatteConsistency(consistency, options.consistency, (dir / "mattes").string());
}

void CheckVolumeReproducesMattes(const fs::path& dir, const Volume& volume, const RunOptions& options,
                                 Progress& progress) {
  const auto [views, mattes] = LoadViewsAndMattes(dir);
  const std::vector<ViewReproduction> reproduction = MeasureReproduction(volume, views, mattes, options.reproduction);
  double recall = 0, precision = 0;
  for (const ViewReproduction& view : reproduction) {
    recall += view.recall / double(reproduction.size());
    precision += view.precision / double(reproduction.size());
  }
  progress.Say("reconstruct", Str("the volume reproduces the mattes: mean recall ", std::round(recall * 1000) / 1000,
                                  ", precision ", std::round(precision * 1000) / 1000));
  CheckReproduction(reproduction, options.reproduction);
}

}  // namespace

void RunOptions::Check() const {
  if (workspace.empty()) Fail("run: the workspace folder is empty");
  matte.Check();
  calibrate.Check();
  reconstruct.Check();
  compress.Check();
  orbit.Check();
  consistency.Check();
  reproduction.Check();
}

void CheckRunWorkspace(const RunOptions& options) {
  options.Check();
  const fs::path& dir = options.workspace;
  if (!fs::is_directory(dir)) Fail(dir.string(), ": no such workspace folder");
  if (NeedsMattes(dir) || NeedsCameras(dir)) {
    const fs::path images = dir / "images";
    const std::string why = NeedsMattes(dir) && NeedsCameras(dir) ? "mattes/ and sparse/ are missing"
                            : NeedsMattes(dir)                    ? "mattes/ is missing"
                                                                  : "sparse/ is missing";
    if (!fs::is_directory(images))
      Fail(images.string(), ": missing; ", why, ", so the photos of the tree are needed (PNG, JPEG, TIFF or BMP)");
    if (FindPhotos(images).empty()) Fail(images.string(), ": no photos (png, jpg, tif, bmp, exr); ", why);
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

  // Photos alone: the cameras first (features everywhere, bounds from the sparse points), so that
  // the mattes can be checked against each other and the disagreeing ones matted again inside
  // the hull of the others; then the bounds from the final mattes.
  const bool photos_alone = NeedsMattes(dir) && NeedsCameras(dir) && options.calibrate_first;
  const auto calibrate = [&] {
    CalibrateOptions calibrate = options.calibrate;
    calibrate.force = calibrate.force || options.force;
    const CalibrateReport report = CalibrateWorkspace(dir, calibrate, progress);
    progress.Say("calibrate", Str(report.registered, "/", report.images, " photos registered, mean reprojection error ",
                                  report.mean_reprojection_error, " px"));
  };
  if (photos_alone) stage("calibrate", true, "", calibrate);
  stage("matte", NeedsMattes(dir), "mattes/ exists", [&] {
    MatteWorkspaceOptions matte = options.matte;
    matte.force = matte.force || options.force;
    // With the cameras known, a matte outside the coverage limits may still be mended by the
    // re-matting below; the check stage applies the limits after it.
    if (photos_alone) {
      matte.coverage.min_coverage = 0;
      matte.coverage.max_coverage = 1;
    }
    MatteWorkspace(dir, matte, progress);
    if (photos_alone) {
      HullRematteOptions rematte = options.rematte;
      rematte.matte = options.matte.matte;
      RematteWorkspaceFromHull(dir, rematte, progress);
      // A matte left (almost) empty would empty the hull that bounds the tree: name it first.
      if (options.guards) {
        const auto [views, mattes] = LoadViewsAndMattes(dir);
        CheckMatteCoverages(dir, views, mattes, options);
      }
      UpdateBoundsFromMattes(dir, options.calibrate.hull, progress);
    }
  });
  if (!photos_alone) stage("calibrate", NeedsCameras(dir), "sparse/ exists", calibrate);
  stage("check", options.guards, "--no-guards", [&] { CheckMattes(dir, options, progress); });
  // A resumable stage runs when --force or when its record does not match; the record is dropped
  // before it runs and written once it finished. `replace`: its outputs may be replaced.
  auto resumable = [&](const StageRecipe& recipe, auto&& work) {
    stage(recipe.stage.c_str(), options.force || !StageIsUpToDate(dir, recipe), kUpToDate, [&] {
      const bool replace = options.force || StageOwnsOutputs(dir, recipe);
      ForgetStage(dir, recipe);
      work(replace);
      RecordStage(dir, recipe);
    });
  };
  resumable(ReconstructRecipe(options), [&](bool replace) {
    const Volume volume = ReconstructWorkspace(dir, {options.reconstruct, replace}, progress);
    if (options.guards) CheckVolumeReproducesMattes(dir, volume, options, progress);
  });
  result.asset = dir / "tree.vtree";
  resumable(CompressRecipe(options), [&](bool replace) {
    CompressWorkspaceOptions compress;
    compress.compress = options.compress;
    compress.force = replace;
    result.compressed = CompressWorkspace(dir, compress, progress);
    result.asset = result.compressed->asset;
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
    evaluate.asset = result.asset;
    evaluate.report = report;
    evaluate.force = evaluate.force || options.force;
    result.evaluation = EvaluateWorkspace(dir, evaluate, progress);
  });
  return result;
}

}  // namespace voltree
