// Scene benchmark: ms per frame on this machine's GL (llvmpipe here) for one tree (finest level
// unpruned and pruned, pruned + LOD) and for scenes of 12 and 290 trees (samples/scenes), with
// billboards and fragments per frame, instances drawn/culled and GPU memory; then frame time
// against the number of trees (the first N instances of forest_290 seen from its orbit). Frames are drawn without
// read-back; the median over the orbit frames is reported.
//   voltree-bench-scene [--assets DIR] [--build] [--scenes samples/scenes] [--size 1024] [--frames 8]
//                       [--json ms_vs_trees.json] [--dolly docs/figures/lod_dolly.png]
// --build makes missing assets in DIR with the voltree binary next to the bench folder, as
// samples/scenes/make_assets.sh does (24 views at 384x384, 6 levels), plus oak-unpruned.vtree
// (reconstruct --prune 1: no visibility pruning) for the first row.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/contact_sheet.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/framebuffer.h"
#include "render/gl_context.h"
#include "render/orbit.h"
#include "render/scene_renderer.h"

using namespace voltree;
namespace fs = std::filesystem;

namespace {

struct Row {
  std::string name;
  size_t trees = 0;
  double drawn = 0, culled = 0, cells = 0, billboards = 0;
  double median_ms = 0, traversal_ms = 0;
  double fragments = -1;  // per frame, all trees; -1 where the driver cannot count them
  size_t gpu_bytes = 0;
};

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

Row Measure(SceneRenderer& renderer, const std::vector<View>& cameras, const SceneRenderOptions& options,
            const std::string& name) {
  Row row{name, renderer.scene().instances.size()};
  Framebuffer target(cameras[0].camera.width, cameras[0].camera.height, ColorFormat::kRGBA8);
  target.Bind();
  renderer.ResetLodHistory();
  auto frame = [&](const View& camera) {
    target.Clear(0, 0, 0, 0);
    return renderer.Draw(camera, options);
  };
  frame(cameras[0]);  // warm-up: shader compile, buffer growth
  std::vector<double> ms, traversal;
  for (const View& camera : cameras) {
    const SceneFrameStats stats = frame(camera);
    ms.push_back(stats.frame_ms);
    traversal.push_back(stats.trees.traversal_ms);
    const double n = double(cameras.size());
    row.drawn += double(stats.instances_drawn) / n, row.culled += double(stats.instances_culled) / n;
    row.cells += double(stats.trees.cells) / n, row.billboards += double(stats.trees.billboards) / n;
  }
  row.median_ms = Median(ms);
  row.traversal_ms = Median(traversal);
  row.gpu_bytes = renderer.GpuBytes().Total();
  // Fragments in a pass of their own, so the queries' cost stays out of the timings.
  SceneRenderOptions counted = options;
  counted.tree.count_fragments = true;
  renderer.ResetLodHistory();
  double fragments = 0;
  for (const View& camera : cameras) {
    target.Clear(0, 0, 0, 0);
    const SceneFrameStats stats = renderer.Draw(camera, counted);
    if (stats.trees.fragments < 0 && stats.trees.cells > 0) return row;  // not countable here
    fragments += double(std::max<int64_t>(stats.trees.fragments, 0)) / double(cameras.size());
  }
  row.fragments = fragments;
  return row;
}

void Run(const std::string& command) {
  std::printf("  $ %s\n", command.c_str());
  std::fflush(stdout);
  if (std::system(command.c_str()) != 0) Fail("bench: command failed: ", command);
}

void BuildAssets(const fs::path& dir, const fs::path& voltree) {
  if (!fs::exists(voltree)) Fail("bench: --build needs the voltree binary at ", voltree.string());
  fs::create_directories(dir / "work");
  const std::string v = voltree.string();
  for (const std::string tree : {"oak", "pine", "young-oak"}) {
    if (fs::exists(dir / (tree + ".vtree"))) continue;
    const std::string work = (dir / "work" / tree).string();
    Run(v + " synth --tree " + tree + " --views 24 --size 384x384 --quiet --force -o " + work);
    Run(v + " reconstruct " + work + " --levels 6 --quiet --force");
    Run(v + " compress " + work + " -o " + (dir / (tree + ".vtree")).string() + " --quiet");
  }
  if (!fs::exists(dir / "oak-unpruned.vtree")) {
    const std::string work = (dir / "work" / "oak").string();
    Run(v + " reconstruct " + work + " --levels 6 --prune 1 --quiet --force");
    Run(v + " compress " + work + " -o " + (dir / "oak-unpruned.vtree").string() + " --quiet");
  }
}

// A scene of one instance of `asset` at the origin, without ground (the single-tree rows).
Scene OneTree(const fs::path& asset) {
  Scene scene;
  scene.name = asset.string();
  scene.assets = {{"tree", asset}};
  scene.instances = {{0, {}}};
  return scene;
}

// Cameras scaled away from the asset's centre (same focal length: the tree gets smaller).
std::vector<View> Farther(std::vector<View> cameras, const VtreeAsset& asset, double factor) {
  const Eigen::Vector3d centre = 0.5 * (asset.bounds_min + asset.bounds_max);
  for (View& view : cameras)
    view.pose = Pose::LookAt(centre + factor * (view.pose.Center() - centre), centre, Eigen::Vector3d::UnitZ());
  return cameras;
}

// A dolly out across the forest, level-tinted, screen rule above and planes below.
void WriteDolly(const Scene& forest, const std::vector<VtreeAsset>& assets, const fs::path& output) {
  SceneRenderer renderer(forest, assets);
  constexpr int kFrames = 6, kSize = 384;
  std::vector<Image8> images;
  for (LodRule rule : {LodRule::kScreen, LodRule::kPlanes}) {
    SceneRenderOptions options;
    options.tree.lod.rule = rule;
    options.tree.tint_levels = true;
    options.tree.background = {0.53f, 0.7f, 0.9f, 1};
    renderer.ResetLodHistory();
    for (int i = 0; i < kFrames; ++i) {
      const double back = 30.0 * ((1 << i) - 1);  // 0, 30, 90, 210, 450, 930 m behind the start
      View view;
      view.camera = Camera::Pinhole(kSize, kSize, 0.45 * kSize, 0.45 * kSize, 0.5 * kSize, 0.5 * kSize);  // ~96 deg
      view.pose = Pose::LookAt(Eigen::Vector3d(-20, -80 - back, 12), Eigen::Vector3d(10, 10 - back, 0),
                               Eigen::Vector3d::UnitZ());
      images.push_back(renderer.Render(view, options));
    }
  }
  ContactSheetOptions sheet;
  sheet.columns = kFrames;
  sheet.thumbnail_width = 192;
  const Image8 image = MakeContactSheet(images, sheet);
  fs::create_directories(output.parent_path().empty() ? fs::path(".") : output.parent_path());
  WriteImage(output, image);
  std::printf("wrote %s (%dx%d): dolly out, levels tinted (0 red .. 5 blue); top screen rule, bottom planes\n",
              output.string().c_str(), image.width, image.height);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"voltree scene benchmark: ms per frame for one tree and scenes of 12 and 290 trees"};
  std::string assets_dir = "/tmp/voltree-bench-scene-assets", scenes_dir = "samples/scenes", json_path, dolly;
  int size = 1024, frames = 8;
  bool build = false;
  app.add_option("--assets", assets_dir, "Folder with oak.vtree, pine.vtree, young-oak.vtree (and oak-unpruned.vtree)")
      ->capture_default_str();
  app.add_flag("--build", build, "Build missing assets with the voltree binary first");
  app.add_option("--scenes", scenes_dir, "Folder with forest_290.json and square_12.json")->capture_default_str();
  app.add_option("--size", size, "Square frame size")->capture_default_str();
  app.add_option("--frames", frames, "Orbit frames per row")->capture_default_str();
  app.add_option("--json", json_path, "Also write ms per frame against the number of trees as JSON");
  app.add_option("--dolly", dolly, "Also write the LOD dolly-out contact sheet (PNG)");
  CLI11_PARSE(app, argc, argv);
  try {
    const fs::path assets = assets_dir;
    if (build) BuildAssets(assets, fs::absolute(argv[0]).parent_path().parent_path() / "voltree");
    GlContext context;
    OrbitOptions orbit;
    orbit.frames = frames;
    orbit.width = orbit.height = size;
    std::vector<Row> rows;

    // One tree: its own orbit (the input views' distance).
    const VtreeAsset oak = ReadAsset(assets / "oak.vtree");
    const std::vector<View> oak_cameras = OrbitCameras(oak, orbit);
    const int finest = int(oak.levels.size()) - 1;
    SceneRenderOptions forced;
    forced.tree.lod.forced_level = finest;
    if (fs::exists(assets / "oak-unpruned.vtree")) {
      SceneRenderer unpruned(OneTree(assets / "oak-unpruned.vtree"), {ReadAsset(assets / "oak-unpruned.vtree")});
      rows.push_back(Measure(unpruned, oak_cameras, forced, Str("1 oak, level ", finest, ", unpruned")));
    }
    SceneRenderer one(OneTree(assets / "oak.vtree"), {oak});
    rows.push_back(Measure(one, oak_cameras, forced, Str("1 oak, level ", finest, ", pruned")));
    rows.push_back(Measure(one, oak_cameras, {}, "1 oak, pruned + LOD"));
    SceneRenderOptions planes;
    planes.tree.lod.rule = LodRule::kPlanes;
    rows.push_back(Measure(one, oak_cameras, planes, "1 oak, pruned + LOD planes"));
    rows.push_back(Measure(one, Farther(oak_cameras, oak, 4), {}, "1 oak, LOD, 4x distance"));

    // Scenes, on their orbits.
    for (const std::string name : {"square_12", "forest_290"}) {
      const Scene scene = LoadScene(fs::path(scenes_dir) / (name + ".json"), {assets});
      SceneRenderer renderer(scene, ReadSceneAssets(scene));
      const std::vector<View> cameras = SceneOrbitCameras(renderer.Bounds(1), orbit);
      rows.push_back(Measure(renderer, cameras, {}, name + ", LOD"));
      if (name == "forest_290") rows.push_back(Measure(renderer, cameras, planes, name + ", LOD planes"));
    }

    std::printf("%s, %dx%d, %d orbit frames per row; assets in %s\n\n", context.renderer().c_str(), size, size, frames,
                assets.string().c_str());
    std::printf("%-30s %6s %7s %7s %9s %11s %10s %13s %11s %9s\n", "frames", "trees", "drawn", "culled", "cells",
                "billboards", "median ms", "traversal ms", "fragments", "GPU KiB");
    for (const Row& r : rows)
      std::printf("%-30s %6zu %7.1f %7.1f %9.0f %11.0f %10.1f %13.1f %11.0f %9.1f\n", r.name.c_str(), r.trees, r.drawn,
                  r.culled, r.cells, r.billboards, r.median_ms, r.traversal_ms, r.fragments, r.gpu_bytes / 1024.0);

    // Frame time against the number of trees: the first N of the forest, from the full forest's orbit.
    const Scene forest = LoadScene(fs::path(scenes_dir) / "forest_290.json", {assets});
    const std::vector<VtreeAsset> forest_assets = ReadSceneAssets(forest);
    std::vector<View> forest_cameras;
    {
      SceneRenderer full(forest, forest_assets);
      forest_cameras = SceneOrbitCameras(full.Bounds(1), orbit);
    }
    nlohmann::json sweep = nlohmann::json::array();
    std::printf("\nforest subsets (first N instances of forest_290, its orbit):\n%6s %10s %11s %11s\n", "trees",
                "median ms", "billboards", "fragments");
    for (size_t n : {1, 12, 50, 100, 200, 290}) {
      Scene subset = forest;
      subset.instances.resize(std::min(n, forest.instances.size()));
      SceneRenderer renderer(subset, forest_assets);
      const Row r = Measure(renderer, forest_cameras, {}, Str(n, " trees"));
      std::printf("%6zu %10.1f %11.0f %11.0f\n", n, r.median_ms, r.billboards, r.fragments);
      sweep.push_back({{"trees", n},
                       {"median_ms", r.median_ms},
                       {"fragments", r.fragments},
                       {"billboards", r.billboards},
                       {"drawn", r.drawn},
                       {"gpu_bytes", r.gpu_bytes}});
    }
    if (!json_path.empty()) {
      nlohmann::json out = {
          {"renderer", context.renderer()}, {"size", size}, {"frames", frames}, {"forest_subsets", sweep}};
      nlohmann::json table = nlohmann::json::array();
      for (const Row& r : rows)
        table.push_back({{"name", r.name},
                         {"trees", r.trees},
                         {"median_ms", r.median_ms},
                         {"fragments", r.fragments},
                         {"billboards", r.billboards},
                         {"cells", r.cells},
                         {"drawn", r.drawn},
                         {"culled", r.culled},
                         {"gpu_bytes", r.gpu_bytes}});
      out["rows"] = table;
      WriteFileAtomic(json_path, out.dump(2) + "\n");
      std::printf("wrote %s\n", json_path.c_str());
    }
    if (!dolly.empty()) WriteDolly(forest, forest_assets, dolly);
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-scene: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
