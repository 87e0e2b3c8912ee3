// The user's path measured: photos alone in, asset out. For each tree and backdrop, the studio
// photographs a set (true cameras, mattes and held-out views known); `run` then works from the
// photos alone (automatic mattes, COLMAP) and, for comparison, from the same photos with the
// true cameras and mattes. Prints one row per (tree, backdrop, input): photos registered, camera
// error after similarity alignment, matte MSE and SAD against the truth (mean and worst photo),
// held-out RGB PSNR, alpha PSNR, precision, recall, and seconds per stage. A run that a guard
// stopped prints the guard's first line instead.
//   voltree-bench-capture --trees oak,pine --backdrops realistic,plain --views 24 --size 512
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "capture/calibrate.h"
#include "capture/calibrate_accuracy.h"
#include "capture/colmap_binary.h"
#include "capture/matte.h"
#include "capture/photo_folder.h"
#include "core/colmap_model.h"
#include "core/error.h"
#include "core/image.h"
#include "pipeline/run_workspace.h"
#include "samples/studio.h"
#include "samples/tree_source.h"

namespace fs = std::filesystem;
using namespace voltree;

namespace {

struct BenchOptions {
  std::vector<std::string> trees{"oak", "pine", "young-oak"};
  std::vector<std::string> backdrops{"realistic", "plain"};
  int views = 24;
  int held_out = 8;
  int size = 512;
  double min_elevation = 5;
  int max_features = CalibrateOptions{}.max_features;  // what `run` and `calibrate` use
  int levels = 7;
  bool deepen = true;    // as `run` without --levels: more levels where the photos fill them and the budget holds
  std::string up = "y";  // of mesh files (glTF convention)
  bool truth_runs = true;
  fs::path work = fs::temp_directory_path() / "voltree_bench_capture";
};

struct MatteSummary {
  double mse_mean = 0, mse_worst = 0, sad_mean = 0, sad_worst = 0;
};

MatteSummary CompareWithTruth(const fs::path& dir, const fs::path& truth_mattes) {
  MatteSummary summary;
  int count = 0;
  for (const fs::path& photo : ListPhotos(dir / "images")) {
    const fs::path estimate = dir / "mattes" / (photo.stem().string() + ".png");
    if (!fs::exists(estimate)) continue;
    const MatteError error = CompareMattes(ReadImage8(estimate, 1), ReadImage8(FindUserMatte(truth_mattes, photo), 1));
    summary.mse_mean += error.mse / 1000;  // as a fraction, like the targets
    summary.sad_mean += error.sad;
    summary.mse_worst = std::max(summary.mse_worst, error.mse / 1000);
    summary.sad_worst = std::max(summary.sad_worst, error.sad);
    ++count;
  }
  if (count) {
    summary.mse_mean /= count;
    summary.sad_mean /= count;
  }
  return summary;
}

double StageSeconds(const RunResult& result, const std::string& stage) {
  for (const StageTime& time : result.stages)
    if (time.stage == stage && time.what == "ran") return time.seconds;
  return 0;
}

void PrintRow(const std::string& tree, const std::string& backdrop, const std::string& input, const fs::path& dir,
              const fs::path& truth, const RunResult* result, const std::string& stopped) {
  std::string registered = "-", cameras = "-";
  const std::vector<std::string> photos = PhotoNames(FindPhotos(dir / "images"));
  if (fs::exists(dir / "sparse") && input == "photos") {
    const std::vector<View> estimated = ReadColmapModel(dir / "sparse").Views();
    // Per ring: the studio names ring 0's photos first (view_000 ... view_{n/2-1}).
    size_t low = 0;
    for (const View& view : estimated)
      if (std::stoi(view.name.substr(5, 3)) < int(photos.size()) / 2) ++low;
    registered = Str(low, " + ", estimated.size() - low, " / ", photos.size());
    if (estimated.size() >= 3) {
      const CameraAccuracy accuracy = CompareCameras(estimated, ReadColmapModel(truth / "sparse").Views());
      // The worst photo of each ring, all aligned together.
      double rotation[2] = {0, 0}, centre[2] = {0, 0};
      for (const CameraAccuracy::PerView& view : accuracy.views) {
        const int ring = std::stoi(view.name.substr(5, 3)) < int(photos.size()) / 2 ? 0 : 1;
        rotation[ring] = std::max(rotation[ring], view.rotation_degrees);
        centre[ring] = std::max(centre[ring], view.center_error);
      }
      char text[96];
      std::snprintf(text, sizeof text, "%.2f° / %.2f %% (low), %.2f° / %.2f %% (high)", rotation[0], 100 * centre[0],
                    rotation[1], 100 * centre[1]);
      cameras = text;
    }
  } else if (input == "truth") {
    registered = "true";
    cameras = "true";
  }
  std::string mattes = "-";
  if (input == "photos" && fs::exists(dir / "mattes")) {
    const MatteSummary m = CompareWithTruth(dir, truth / "mattes");
    char text[96];
    std::snprintf(text, sizeof text, "%.4f / %.4f | %.1f / %.1f", m.mse_mean, m.mse_worst, m.sad_mean, m.sad_worst);
    mattes = text;
  } else {
    mattes = input == "truth" ? "true | true" : "- | -";
  }
  std::printf("| %s | %s | %s | %s | %s | %s |", tree.c_str(), backdrop.c_str(), input.c_str(), registered.c_str(),
              cameras.c_str(), mattes.c_str());
  if (result) {
    const MetricsReport& held = result->evaluation.table.Overall(ViewSet::kHeldOut);
    double mean[6] = {};
    const auto summaries = held.Summaries();
    for (size_t i = 0; i < 6 && i < summaries.size(); ++i) mean[i] = summaries[i].second.mean;
    std::printf(" %.2f | %.2f | %.3f | %.3f | %.0f / %.0f / %.0f / %.0f |", mean[0], mean[2], mean[3], mean[4],
                StageSeconds(*result, "matte"), StageSeconds(*result, "calibrate"),
                StageSeconds(*result, "reconstruct") + StageSeconds(*result, "check"),
                StageSeconds(*result, "compress") + StageSeconds(*result, "orbit") + StageSeconds(*result, "eval"));
  } else {
    std::printf(" stopped: %s | | | | |", stopped.c_str());
  }
  std::printf("\n");
  std::fflush(stdout);
}

void RunCase(const std::string& tree, const std::string& backdrop, const BenchOptions& bench) {
  const std::string label = fs::path(tree).stem().string() + "_" + backdrop;
  const fs::path truth = bench.work / label / "truth_set";
  StudioOptions studio;
  studio.views = bench.views;
  studio.held_out = bench.held_out;
  studio.width = studio.height = bench.size;
  studio.min_elevation_degrees = bench.min_elevation;
  studio.backdrop = BackdropStyleFromName(backdrop);
  TreeSource source;
  source.tree = tree;
  const std::optional<UpAxis> up = UpAxisFromName(bench.up);
  if (up) source.up = *up;
  studio.tree_name = TreeSourceName(source);
  Progress quiet(true);
  std::vector<std::string> warnings;
  PhotographTree(LoadTreeMesh(source, quiet, &warnings), studio, truth, quiet, /*force=*/true);

  RunOptions options;
  options.calibrate.max_image_size = bench.size;
  options.calibrate.max_features = bench.max_features;
  options.reconstruct.levels = bench.levels;
  if (bench.deepen) options.reconstruct.deepen_within_bytes = options.compress.max_bytes;
  options.evaluate.each_level = false;
  options.orbit.frames = 4;
  options.force = true;
  const std::string name = fs::path(tree).stem().string();

  // From the photos alone: images/ and the held-out truth, nothing else.
  const fs::path photos = bench.work / label / "photos";
  fs::remove_all(photos);
  fs::create_directories(photos);
  fs::copy(truth / "images", photos / "images", fs::copy_options::recursive);
  fs::copy(truth / "truth", photos / "truth", fs::copy_options::recursive);
  // The input photos' true cameras, for the evaluation to move the held-out views into the frame
  // COLMAP found (pipeline/evaluation_truth.h).
  fs::copy(truth / "sparse", photos / "truth" / "input_sparse", fs::copy_options::recursive);
  options.workspace = photos;
  try {
    const RunResult result = RunWorkspace(options, quiet);
    PrintRow(name, backdrop, "photos", photos, truth, &result, "");
  } catch (const Error& error) {
    std::string first = error.what();
    PrintRow(name, backdrop, "photos", photos, truth, nullptr, first.substr(0, std::min<size_t>(first.find('\n'), 90)));
  }
  if (!bench.truth_runs) return;
  const fs::path known = bench.work / label / "known";
  fs::remove_all(known);
  fs::copy(truth, known, fs::copy_options::recursive);
  options.workspace = known;
  try {
    const RunResult result = RunWorkspace(options, quiet);
    PrintRow(name, backdrop, "truth", known, truth, &result, "");
  } catch (const Error& error) {
    std::string first = error.what();
    PrintRow(name, backdrop, "truth", known, truth, nullptr, first.substr(0, std::min<size_t>(first.find('\n'), 90)));
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Capture benchmark: run from photos alone against the same photos with the true cameras and mattes"};
  BenchOptions bench;
  app.add_option("--trees", bench.trees, "Presets or mesh files")->delimiter(',')->capture_default_str();
  app.add_option("--backdrops", bench.backdrops, "realistic and/or plain")->delimiter(',')->capture_default_str();
  app.add_option("--views", bench.views, "Photos per set")->capture_default_str();
  app.add_option("--held-out", bench.held_out, "Held-out views per set")->capture_default_str();
  app.add_option("--size", bench.size, "Photo width and height (pixels)")->capture_default_str();
  app.add_option("--min-elevation", bench.min_elevation, "Lowest ring (degrees)")->capture_default_str();
  app.add_option("--max-features", bench.max_features, "SIFT features per photo at most")->capture_default_str();
  auto* levels = app.add_option("--levels", bench.levels,
                                "Octree levels (not given: 7, and more where the photos fill them and the asset is "
                                "predicted to fit the byte budget, as run does)")
                     ->capture_default_str();
  app.add_option("--up", bench.up, "Up axis of mesh files: y or z")->capture_default_str();
  app.add_flag("!--no-truth", bench.truth_runs, "Skip the runs with the true cameras and mattes");
  app.add_option("--work", bench.work, "Folder for the sets (replaced)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  bench.deepen = levels->count() == 0;
  try {
    std::printf(
        "%d views (+%d held out) at %d², lowest ring %.0f°, %d features, %d levels%s; camera error per ring: "
        "worst rotation / worst centre (%% of the camera distance); matte MSE as a fraction, SAD in thousands\n",
        bench.views, bench.held_out, bench.size, bench.min_elevation, bench.max_features, bench.levels,
        bench.deepen ? " (more where the byte budget holds them)" : "");
    std::printf(
        "| tree | backdrop | input | registered (low + high ring) | camera error | matte MSE mean / worst | SAD mean / "
        "worst | "
        "RGB PSNR | alpha PSNR | precision | recall | s: matte / calibrate / reconstruct / rest |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& tree : bench.trees)
      for (const std::string& backdrop : bench.backdrops) RunCase(tree, backdrop, bench);
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-capture: %s\n", error.what());
    return 1;
  }
  return 0;
}
