// Render benchmark: ms per frame at 1024x1024 for one tree on this machine's GL (llvmpipe here):
// every forced level (the finest last), and the screen-space LOD at 1x to 16x the input
// views' mean distance and where the tree fills a third of the frame's height (a typical
// viewing distance), each beside the finest level at that distance. Billboards are the pruned set the asset stores; the
// table also prints how many there were before pruning, and per frame the fragments shaded (quads trimmed to their
// alpha's extent, and whole), the pixels covered and the overdraw (fragments per covered pixel).
//   voltree-bench-render ASSET [--size 1024] [--frames 12]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/vtree.h"
#include "render/gl_context.h"
#include "render/orbit.h"
#include "render/tree_renderer.h"

using namespace voltree;

namespace {

struct Row {
  std::string name;
  double median_ms = 0, traversal_ms = 0, billboards = 0, cells = 0;
  double fragments = -1, untrimmed_fragments = -1, covered = 0;  // per frame; -1: not counted
  int min_level = 0, max_level = 0;
};

// Mean fragments per frame with `options` (-1 where the driver cannot count them).
double MeanFragments(TreeRenderer& renderer, const std::vector<View>& cameras, TreeRenderOptions options) {
  options.count_fragments = true;
  renderer.ResetLodHistory();
  double sum = 0;
  for (const View& camera : cameras) {
    FrameStats stats;
    renderer.Render(camera, options, &stats);
    if (stats.fragments < 0) return -1;
    sum += double(stats.fragments);
  }
  return sum / double(cameras.size());
}

Row Measure(TreeRenderer& renderer, const std::vector<View>& cameras, const TreeRenderOptions& options,
            const std::string& name) {
  Row row{name};
  std::vector<double> ms, traversal;
  row.min_level = 1 << 30;
  renderer.ResetLodHistory();
  renderer.Render(cameras[0], options);  // warm-up: shader compile, buffer growth
  for (const View& camera : cameras) {
    FrameStats stats;
    const Image8 image = renderer.Render(camera, options, &stats);
    for (size_t i = 3; i < image.pixels.size(); i += 4) row.covered += image.pixels[i] > 0 ? 1.0 / cameras.size() : 0;
    ms.push_back(stats.frame_ms);
    traversal.push_back(stats.traversal_ms);
    row.billboards += double(stats.billboards) / double(cameras.size());
    row.cells += double(stats.cells) / double(cameras.size());
    row.min_level = std::min(row.min_level, stats.min_level);
    row.max_level = std::max(row.max_level, stats.max_level);
  }
  std::sort(ms.begin(), ms.end());
  std::sort(traversal.begin(), traversal.end());
  row.median_ms = ms[ms.size() / 2];
  row.traversal_ms = traversal[traversal.size() / 2];
  // Counted apart: the query's own cost stays out of the timings.
  row.fragments = MeanFragments(renderer, cameras, options);
  TreeRenderOptions untrimmed = options;
  untrimmed.trim_quads = false;
  row.untrimmed_fragments = MeanFragments(renderer, cameras, untrimmed);
  return row;
}

std::vector<View> Scaled(std::vector<View> cameras, const VtreeAsset& asset, double factor) {
  const Eigen::Vector3d centre = 0.5 * (asset.bounds_min + asset.bounds_max);
  for (View& view : cameras) {
    const Eigen::Vector3d eye = centre + factor * (view.pose.Center() - centre);
    view.pose = Pose::LookAt(eye, centre, Eigen::Vector3d::UnitZ());
    // Keep the focal length: the tree gets smaller on screen, as when walking away.
  }
  return cameras;
}

// Mean over the frames of the share of the frame's rows where the tree covers a pixel.
double HeightShare(TreeRenderer& renderer, const std::vector<View>& cameras) {
  double sum = 0;
  for (const View& camera : cameras) {
    const Image8 image = renderer.Render(camera, {});
    int top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        if (image.at(x, y, 3) > 0) top = std::min(top, y), bottom = std::max(bottom, y);
    sum += bottom >= top ? double(bottom - top + 1) / image.height : 0.0;
  }
  return sum / double(cameras.size());
}

// The distance factor at which the tree fills `share` of the frame's height ("a typical viewing
// distance"). Its height on screen goes about as 1 / distance, so a few fixed-point steps settle.
double FactorForHeightShare(TreeRenderer& renderer, const std::vector<View>& cameras, const VtreeAsset& asset,
                            double share) {
  double factor = 1;
  for (int step = 0; step < 4; ++step) {
    const double now = HeightShare(renderer, Scaled(cameras, asset, factor));
    if (now <= 0) break;
    factor *= now / share;
  }
  return factor;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"voltree render benchmark: ms per frame by level and LOD distance"};
  std::string path;
  int size = 1024, frames = 12;
  app.add_option("ASSET", path, "A .vtree asset (e.g. from synth + reconstruct + compress)")->required();
  app.add_option("--size", size, "Square frame size")->capture_default_str();
  app.add_option("--frames", frames, "Orbit frames per row")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const VtreeAsset asset = ReadAsset(path);
    GlContext context;
    TreeRenderer renderer(asset);
    OrbitOptions orbit;
    orbit.frames = frames;
    orbit.width = orbit.height = size;
    const std::vector<View> cameras = OrbitCameras(asset, orbit);
    std::printf("%s: %zu levels, %zu cells, %zu billboards (%s)\n%s, %dx%d, %d orbit frames per row\n\n", path.c_str(),
                asset.levels.size(), asset.CellCount(), asset.BillboardCount(), "pruned, as stored",
                context.renderer().c_str(), size, size, frames);
    std::vector<Row> rows;
    for (int level = 0; level < int(asset.levels.size()); ++level) {
      TreeRenderOptions options;
      options.lod.forced_level = level;
      rows.push_back(Measure(renderer, cameras, options,
                             Str("level ", level, level + 1 == int(asset.levels.size()) ? " (finest)" : "")));
    }
    TreeRenderOptions finest;
    finest.lod.forced_level = int(asset.levels.size()) - 1;
    const double third = FactorForHeightShare(renderer, cameras, asset, 1.0 / 3);
    char third_name[32];
    std::snprintf(third_name, sizeof third_name, "%.2f", third);
    std::printf("the tree fills %.3f of the frame's height at 1x, a third at %sx (the \"third\" rows)\n\n",
                HeightShare(renderer, cameras), third_name);
    for (double factor : {1.0, third, 2.0, 3.0, 4.0, 8.0, 16.0}) {
      const std::string at = factor == third ? Str("third, ", third_name, "x") : Str(factor, "x");
      if (factor > 1)  // what the LOD saves at this distance
        rows.push_back(Measure(renderer, Scaled(cameras, asset, factor), finest, Str("finest at ", at)));
      rows.push_back(Measure(renderer, Scaled(cameras, asset, factor), {}, Str("LOD at ", at)));
    }
    std::printf("%-24s %8s %10s %10s %10s %12s %11s %11s %11s %9s\n", "frames", "levels", "cells", "billboards",
                "median ms", "traversal ms", "fragments", "untrimmed", "covered px", "overdraw");
    for (const Row& r : rows)
      std::printf("%-24s %4d-%-3d %10.0f %10.0f %10.2f %12.2f %11.0f %11.0f %11.0f %9.2f\n", r.name.c_str(),
                  r.min_level, r.max_level, r.cells, r.billboards, r.median_ms, r.traversal_ms, r.fragments,
                  r.untrimmed_fragments, r.covered, r.covered > 0 ? r.fragments / r.covered : 0.0);
    if (!rows.empty() && rows[0].fragments < 0)
      std::printf("(fragments: -1, %s lacks GL_ARB_pipeline_statistics_query)\n", context.renderer().c_str());
    std::printf("\nbillboards before pruning per level:");
    for (const VtreeLevel& level : asset.levels)
      std::printf(" %llu/%zu", static_cast<unsigned long long>(level.billboards_before_pruning),
                  level.billboards.size());
    std::printf(" (before/kept)\n");
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-render: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
