// Calibration accuracy and speed: for each tree preset, photographs a studio set (true cameras
// known), runs `Calibrate` (COLMAP) on it and prints per-stage COLMAP seconds, registered/total,
// the mean reprojection error, and the cameras' errors after similarity alignment
// (capture/calibrate_accuracy.h), plus how well the normalization found the tree frame: the up
// axis, the origin (trunk base) and the height, against the studio's true frame.
//   voltree-bench-calibrate --views 24 --size 512 --max-features 8192
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/calibrate.h"
#include "capture/calibrate_accuracy.h"
#include "capture/colmap_binary.h"
#include "core/error.h"
#include "core/files.h"
#include "samples/studio.h"
#include "samples/tree_source.h"

namespace fs = std::filesystem;
using namespace voltree;

namespace {

struct BenchOptions {
  std::vector<std::string> trees{"oak", "pine", "young-oak"};
  int views = 24;
  int rings = 2;
  int size = 512;
  double min_elevation = 5;                            // the studio's default lowest ring
  int max_features = CalibrateOptions{}.max_features;  // what `run` and `calibrate` use
  std::string mask = "all";
  fs::path work = fs::temp_directory_path() / "voltree_bench_calibrate";
};

double StageSeconds(const CalibrateReport& report, const std::string& prefix) {
  double seconds = 0;
  for (const auto& [name, s] : report.stage_seconds)
    if (name.rfind(prefix, 0) == 0) seconds += s;
  return seconds;
}

double TrueHeight(const fs::path& scene_json) {
  const auto scene = nlohmann::json::parse(ReadFile(scene_json));
  return scene.at("bounds_max").at(2).get<double>() - scene.at("bounds_min").at(2).get<double>();
}

void RunTree(const std::string& tree, const BenchOptions& bench) {
  const fs::path dir = bench.work / tree;
  StudioOptions studio;
  studio.tree_name = tree;
  studio.views = bench.views;
  studio.rings = bench.rings;
  studio.held_out = 0;
  studio.width = studio.height = bench.size;
  studio.min_elevation_degrees = bench.min_elevation;
  Progress quiet(true);
  TreeSource source;
  source.tree = tree;
  std::vector<std::string> warnings;
  PhotographTree(LoadTreeMesh(source, quiet, &warnings), studio, dir, quiet, /*force=*/true);
  // The studio's cameras are the truth; calibrate must find them again without them.
  const ColmapModel truth = ReadColmapModel(dir / "sparse");
  const double height = TrueHeight(dir / "scene.json");
  fs::remove_all(dir / "sparse");
  fs::remove(dir / "scene.json");

  CalibrateOptions options;
  options.max_image_size = bench.size;
  options.max_features = bench.max_features;
  options.mask = FeatureMaskFromName(bench.mask);
  options.min_registered = 0;      // report partial registrations instead of failing
  options.height_metres = height;  // metres, so that the frame compares with the studio's
  std::printf("| %-9s | %4d | %2d |", tree.c_str(), bench.size, bench.views);
  std::fflush(stdout);
  try {
    const CalibrateReport report = CalibrateWorkspace(dir, options, quiet);
    const CameraAccuracy accuracy = CompareCameras(ReadColmapText(dir / "sparse").Views(), truth.Views());
    // The normalized frame against the true one: heading is free, up, origin and scale are not.
    const Similarity& align = accuracy.estimated_to_true;
    const double up_degrees =
        std::acos(std::clamp((align.rotation * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180 / M_PI;
    const double origin_percent = 100 * align.translation.norm() / height;
    std::printf(" %6.1f | %6.1f | %5.1f | %2d/%-2d | %5.3f | %5.2f / %5.2f | %5.2f / %5.2f | %5.2f | %5.1f | %5.1f |\n",
                StageSeconds(report, "feature"),
                StageSeconds(report, "exhaustive") + StageSeconds(report, "sequential"), StageSeconds(report, "mapper"),
                report.registered, report.images, report.mean_reprojection_error, accuracy.mean_rotation_degrees,
                accuracy.max_rotation_degrees, 100 * accuracy.mean_center_error, 100 * accuracy.max_center_error,
                up_degrees, origin_percent, 100 * (align.scale - 1));
  } catch (const Error& error) {
    std::string first_line = error.what();
    first_line = first_line.substr(0, first_line.find('\n'));
    std::printf(" failed: %s |\n", first_line.c_str());
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Calibration benchmark: COLMAP on studio sets against their true cameras"};
  BenchOptions bench;
  app.add_option("--trees", bench.trees, "Tree presets")->capture_default_str();
  app.add_option("--views", bench.views, "Photos per set")->capture_default_str();
  app.add_option("--rings", bench.rings, "Camera rings")->capture_default_str();
  app.add_option("--size", bench.size, "Photo width and height (pixels)")->capture_default_str();
  app.add_option("--min-elevation", bench.min_elevation, "Lowest ring's elevation (degrees)")->capture_default_str();
  app.add_option("--max-features", bench.max_features, "SIFT features per photo at most")->capture_default_str();
  app.add_option("--mask", bench.mask, "Feature mask: all, tree or near")->capture_default_str();
  app.add_option("--work", bench.work, "Folder for the sets (replaced)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::printf("rings %d, lowest at %.0f deg, max features %d, mask %s; errors after similarity alignment\n",
                bench.rings, bench.min_elevation, bench.max_features, bench.mask.c_str());
    std::printf(
        "| tree      | size | n  | ext s  | match s| map s | reg   | reproj| rot deg mean/max | centre %% mean/max "
        "| up deg| orig %%| scale %%|\n");
    std::printf(
        "|-----------|------|----|--------|--------|-------|-------|-------|------------------|"
        "-------------------|-------|-------|--------|\n");
    for (const std::string& tree : bench.trees) RunTree(tree, bench);
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-calibrate: %s\n", error.what());
    return 1;
  }
  return 0;
}
