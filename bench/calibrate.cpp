// Calibration accuracy and speed: for each tree preset, photographs a studio set (true cameras
// known), runs `Calibrate` (COLMAP) on it and prints per-stage COLMAP seconds, registered/total,
// the mean reprojection error, and the cameras' errors after similarity alignment
// (capture/calibrate_accuracy.h), plus how well the normalization found the tree frame: the up
// axis, the origin (trunk base) and the height, against the studio's true frame.
// COLMAP's threads make its runs differ: --runs N calibrates the same photos N times and prints
// the worst camera of the lowest ring over those runs.
//   voltree-bench-calibrate --views 24 --size 512 --max-features 8192 --runs 3
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
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
  int runs = 1;  // calibrations of the same photos
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

// The studio's ring of its index-th input view: ring r holds views / rings photos, one more for
// the first views % rings rings, named in ring order (samples/studio_rig.cpp).
int RingOfView(int index, int views, int rings) {
  for (int ring = 0, first = 0; ring < rings; ++ring) {
    first += views / rings + (ring < views % rings ? 1 : 0);
    if (index < first) return ring;
  }
  return rings - 1;
}

struct RingError {
  double rotation_degrees = 0, center_error = 0;  // the ring's worst photo
};

std::vector<RingError> WorstPerRing(const CameraAccuracy& accuracy, int views, int rings) {
  std::vector<RingError> worst(rings);
  for (size_t i = 0; i < accuracy.views.size(); ++i) {
    RingError& ring = worst[RingOfView(int(i), views, rings)];
    ring.rotation_degrees = std::max(ring.rotation_degrees, accuracy.views[i].rotation_degrees);
    ring.center_error = std::max(ring.center_error, accuracy.views[i].center_error);
  }
  return worst;
}

// Calibrates the photos in `dir` once; returns the lowest ring's worst photo, or nothing when
// calibration failed (the row says why).
std::optional<RingError> CalibrateOnce(const std::string& tree, const fs::path& dir, const ColmapModel& truth,
                                       double height, const BenchOptions& bench) {
  fs::remove_all(dir / "colmap");
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
  Progress quiet(true);
  try {
    const CalibrateReport report = CalibrateWorkspace(dir, options, quiet);
    const CameraAccuracy accuracy = CompareCameras(ReadColmapText(dir / "sparse").Views(), truth.Views());
    const std::vector<RingError> rings = WorstPerRing(accuracy, bench.views, bench.rings);
    // The normalized frame against the true one: heading is free, up, origin and scale are not.
    const Similarity& align = accuracy.estimated_to_true;
    const double up_degrees =
        std::acos(std::clamp((align.rotation * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180 / M_PI;
    const double origin_percent = 100 * align.translation.norm() / height;
    std::printf(
        " %6.1f | %6.1f | %5.1f | %2d/%-2d | %5.3f | %5.3f / %5.3f | %5.3f / %5.3f | %5.3f / %5.3f | %5.2f | %5.1f | "
        "%5.1f |\n",
        StageSeconds(report, "feature"), StageSeconds(report, "exhaustive") + StageSeconds(report, "sequential"),
        StageSeconds(report, "mapper"), report.registered, report.images, report.mean_reprojection_error,
        accuracy.mean_rotation_degrees, accuracy.max_rotation_degrees, rings.front().rotation_degrees,
        rings.back().rotation_degrees, 100 * accuracy.mean_center_error, 100 * accuracy.max_center_error, up_degrees,
        origin_percent, 100 * (align.scale - 1));
    std::fflush(stdout);
    if (report.registered < report.images) return std::nullopt;
    return rings.front();
  } catch (const Error& error) {
    std::string first_line = error.what();
    first_line = first_line.substr(0, first_line.find('\n'));
    std::printf(" failed: %s |\n", first_line.c_str());
    std::fflush(stdout);
    return std::nullopt;
  }
}

struct TreeSummary {
  std::string tree;
  int runs = 0, complete = 0;  // runs, and those that registered every photo
  RingError worst;             // the lowest ring's worst photo over the complete runs
};

TreeSummary RunTree(const std::string& tree, const BenchOptions& bench) {
  const std::string label = fs::path(tree).stem().string();  // a preset, or a mesh file's name
  const fs::path dir = bench.work / label;
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
  TreeSummary summary{label, bench.runs, 0, {}};
  for (int run = 0; run < bench.runs; ++run)
    if (const std::optional<RingError> lowest = CalibrateOnce(label, dir, truth, height, bench)) {
      ++summary.complete;
      summary.worst.rotation_degrees = std::max(summary.worst.rotation_degrees, lowest->rotation_degrees);
      summary.worst.center_error = std::max(summary.worst.center_error, lowest->center_error);
    }
  return summary;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Calibration benchmark: COLMAP on studio sets against their true cameras"};
  BenchOptions bench;
  app.add_option("--trees", bench.trees, "Presets or mesh files (glTF: Y up)")->delimiter(',')->capture_default_str();
  app.add_option("--views", bench.views, "Photos per set")->capture_default_str();
  app.add_option("--rings", bench.rings, "Camera rings")->capture_default_str();
  app.add_option("--size", bench.size, "Photo width and height (pixels)")->capture_default_str();
  app.add_option("--min-elevation", bench.min_elevation, "Lowest ring's elevation (degrees)")->capture_default_str();
  app.add_option("--max-features", bench.max_features, "SIFT features per photo at most")->capture_default_str();
  app.add_option("--mask", bench.mask, "Feature mask: all, tree or near")->capture_default_str();
  app.add_option("--runs", bench.runs, "Calibrations of each set (COLMAP's runs differ)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--work", bench.work, "Folder for the sets (replaced)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::printf(
        "rings %d, lowest at %.0f deg, max features %d, mask %s, %d run(s) per set; errors after similarity "
        "alignment; rot ring: the worst photo of the lowest / highest ring\n",
        bench.rings, bench.min_elevation, bench.max_features, bench.mask.c_str(), bench.runs);
    std::printf(
        "| tree      | size | n  | ext s  | match s| map s | reg   | reproj| rot deg mean/max | rot ring low/high "
        "| centre %% mean/max | up deg| orig %%| scale %%|\n");
    std::printf(
        "|-----------|------|----|--------|--------|-------|-------|-------|------------------|-------------------|"
        "-------------------|-------|-------|--------|\n");
    std::vector<TreeSummary> summaries;
    for (const std::string& tree : bench.trees) summaries.push_back(RunTree(tree, bench));
    if (bench.runs > 1) {
      std::printf("\nthe lowest ring's worst photo over the runs that registered every photo:\n");
      for (const TreeSummary& summary : summaries)
        std::printf("  %-9s %d/%d runs complete, rotation %.3f deg, centre %.3f %%\n", summary.tree.c_str(),
                    summary.complete, summary.runs, summary.worst.rotation_degrees, 100 * summary.worst.center_error);
    }
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-calibrate: %s\n", error.what());
    return 1;
  }
  return 0;
}
