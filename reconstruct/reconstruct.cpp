#include "reconstruct/reconstruct.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/fixed.h"
#include "reconstruct/auto_levels.h"
#include "reconstruct/carve.h"
#include "reconstruct/grid.h"
#include "reconstruct/matte_stats.h"
#include "core/volume_io.h"

namespace voltree {
namespace {

std::string Gigabytes(size_t bytes) {
  std::ostringstream out;
  out.precision(bytes >= (size_t(1) << 30) ? 3 : 2);
  out << double(bytes) / double(size_t(1) << 30) << " GiB";
  return out.str();
}

// White leaves where no foreground colour is given: colour is then only a placeholder.
Image8 WhiteForeground(const Image8& matte) {
  Image8 out(matte.width, matte.height, 4);
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x)
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = matte.at(x, y);
  return out;
}

void SayFitReport(const BillboardFitReport& report, Progress& progress) {
  for (const BillboardFitLevel& l : report.levels)
    progress.Say("fit", Str("level ", l.level, " (1/", FixedDecimals(l.scale, 1), " scale): alpha PSNR ",
                            FixedDecimals(l.alpha_psnr_before, 2), " -> ", FixedDecimals(l.alpha_psnr_after, 2),
                            " dB, RGB ", FixedDecimals(l.rgb_psnr_before, 2), " -> ",
                            FixedDecimals(l.rgb_psnr_after, 2), " dB at the input views"));
  for (const std::string& warning : report.warnings) progress.Say("fit", "warning: " + warning);
}

}  // namespace

void ReconstructOptions::Check() const {
  if (branching != 2 && branching != 3)
    FailOption("ReconstructOptions.branching", "must be 2 (octree) or 3 (tri-grid), got ", branching);
  if (levels < 1) FailOption("ReconstructOptions.levels", "must be at least 1, got ", levels);
  if (LevelResolution(branching, levels - 1) == 0)
    FailOption("ReconstructOptions.levels", levels, " at branching ", branching,
               " exceeds the 16-bit cell coordinates (at most ", branching == 2 ? 16 : 10, " levels)");
  if (texels < 1 || texels > 64) FailOption("ReconstructOptions.texels", "must be in [1, 64], got ", texels);
  if (threads < 0) FailOption("ReconstructOptions.threads", "must be >= 0, got ", threads);
  if (!(margin >= 0 && margin < 1)) FailOption("ReconstructOptions.margin", "must be in [0, 1), got ", margin);
  if (!(carve_alpha >= 0 && carve_alpha < 1))
    FailOption("ReconstructOptions.carve_alpha", "must be in [0, 1), got ", carve_alpha);
  opacity.Check();
  billboards.Check();
  fit.Check();
}

nlohmann::json ReconstructOptions::ToJson() const {
  // Threads are left out on purpose: the output does not depend on them.
  const bool ceres = opacity.solver == SolverKind::kCeres;
  return {{"levels", levels},
          {"branching", branching},
          {"texels", texels},
          {"prune", billboards.prune},
          {"solver", ceres ? "ceres" : "sart"},
          {"iterations", ceres ? opacity.ceres.iterations : opacity.sart.iterations},
          {"relaxation", opacity.sart.relaxation},
          {"huber", opacity.ceres.huber},
          {"margin", margin},
          {"carve_alpha", carve_alpha},
          {"carve_views", opacity.carve_views},
          {"refine_min_optical_depth", opacity.refine_min_optical_depth},
          {"samples_per_cell", opacity.tomography.samples_per_cell},
          {"epsilon", opacity.tomography.epsilon},
          {"billboard_scale", billboards.scale},
          {"deepen_within_bytes", deepen_within_bytes},
          {"fit", fit.enabled ? nlohmann::json{{"iterations", fit.iterations},
                                               {"prior", fit.prior},
                                               {"alpha_weight", fit.alpha_weight},
                                               {"neighbours", fit.neighbours},
                                               {"neighbour_weight", fit.neighbour_weight}}
                              : nlohmann::json(false)}};
}

size_t AvailableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  size_t value = 0;
  std::string unit;
  while (in >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024;
  return 0;
}

size_t EstimateReconstructBytes(const ReconstructInput& input, const ReconstructOptions& options) {
  // Summed-area tables of every matte, plus one view's colour tables at a time.
  double bytes = 0, largest_image = 0;
  for (const View& view : input.views) {
    const double pixels = double(view.camera.width + 1) * (view.camera.height + 1);
    bytes += pixels * (sizeof(uint64_t) + sizeof(uint32_t));
    largest_image = std::max(largest_image, pixels);
  }
  bytes += largest_image * 4 * sizeof(uint64_t);
  // Dense index grids of every level (all alive while the billboards are made).
  double dense = 0, finest = 1;
  for (int level = 0; level < options.levels; ++level) {
    finest = std::pow(double(options.branching), 3.0 * level);
    dense += finest * sizeof(int32_t);
  }
  bytes += dense;
  // Cells: assume up to a quarter of the finest grid survives carving; per cell sigma, solver
  // buffers (16 chunks), and texels before pruning for every view at every level.
  const double cells = 0.25 * finest * (1.0 + 1.0 / (std::pow(options.branching, 3) - 1));
  bytes += cells * (sizeof(CellCoord) + sizeof(float) + 18 * sizeof(double));
  bytes += cells * double(input.views.size()) * (double(options.texels) * options.texels * 4 + 1);
  bytes += double(options.opacity.tomography.max_stored_bytes);
  return size_t(std::min(bytes, 1e19));
}

void CheckReconstructInput(const ReconstructInput& input, const ReconstructOptions& options) {
  const std::string& src = input.source;
  if (input.views.empty()) Fail(src, ": no views to reconstruct from");
  if (input.views.size() > 65535) Fail(src, ": at most 65535 views, got ", input.views.size());
  if (input.mattes.size() != input.views.size())
    Fail(src, ": ", input.views.size(), " views but ", input.mattes.size(), " mattes");
  if (!input.foreground.empty() && input.foreground.size() != input.views.size())
    Fail(src, ": ", input.views.size(), " views but ", input.foreground.size(), " foreground images");
  for (size_t v = 0; v < input.views.size(); ++v) {
    const View& view = input.views[v];
    try {
      view.camera.Check();
    } catch (const Error& e) {
      Fail(src, ": view '", view.name, "': ", e.what());
    }
    const Image8& matte = input.mattes[v];
    if (matte.channels != 1 || matte.width != view.camera.width || matte.height != view.camera.height)
      Fail(src, ": matte of view '", view.name, "' is ", matte.width, "x", matte.height, "x", matte.channels,
           ", expected ", view.camera.width, "x", view.camera.height, "x1 (the camera's size, grey)");
    if (!input.foreground.empty()) {
      const Image8& fg = input.foreground[v];
      if (fg.channels != 4 || fg.width != view.camera.width || fg.height != view.camera.height)
        Fail(src, ": foreground of view '", view.name, "' is ", fg.width, "x", fg.height, "x", fg.channels,
             ", expected ", view.camera.width, "x", view.camera.height, "x4 (premultiplied RGBA)");
    }
  }
  const Eigen::Vector3d extent = input.bounds_max - input.bounds_min;
  if (!extent.allFinite() || extent.minCoeff() < 0 || extent.maxCoeff() <= 0)
    Fail(src, ": scene bounds [", input.bounds_min.transpose(), "] .. [", input.bounds_max.transpose(),
         "] are empty or not finite");
  double widest_pixels = 0;  // the bounds' largest projected extent over the views
  for (const View& view : input.views) {
    double x0, y0, x1, y1;
    const bool in_front = ProjectBox(view, input.bounds_min, input.bounds_max, &x0, &y0, &x1, &y1);
    if (in_front) widest_pixels = std::max({widest_pixels, x1 - x0, y1 - y0});
    if (!in_front || x1 <= 0 || y1 <= 0 || x0 >= view.camera.width || y0 >= view.camera.height)
      Fail(src, ": view '", view.name, "' does not see the scene bounds [", input.bounds_min.transpose(), "] .. [",
           input.bounds_max.transpose(), "]",
           in_front ? " (they project outside the image)" : " (they are behind or around the camera)",
           "; check the cameras and scene.json");
  }
  if (widest_pixels < 1)
    Fail(src, ": scene bounds [", input.bounds_min.transpose(), "] .. [", input.bounds_max.transpose(),
         "] are smaller than one pixel in every view (", widest_pixels,
         " px at most): there is nothing to "
         "reconstruct in them; check scene.json");
  const uint8_t empty_at = CarveThreshold8(options.carve_alpha);
  bool any_alpha = false;
  for (size_t v = 0; v < input.views.size(); ++v) {
    const Image8& matte = input.mattes[v];
    size_t opaque = 0;
    uint8_t max_alpha = 0;
    for (uint8_t a : matte.pixels) {
      opaque += a >= 250;
      max_alpha = std::max(max_alpha, a);
    }
    any_alpha = any_alpha || max_alpha > empty_at;
    if (double(opaque) > 0.98 * double(matte.pixels.size()))
      Fail(src, ": matte of view '", input.views[v].name, "' is ", int(100.0 * opaque / matte.pixels.size()),
           "% opaque: the mattes look inverted or unmatted (expected the tree opaque, 255, on a transparent, 0, "
           "background)");
  }
  if (!any_alpha)
    Fail(src, ": nothing to reconstruct: every matte is empty (alpha <= ", options.carve_alpha,
         "); expected the tree opaque, 255, on a transparent, 0, background");
  const size_t need = EstimateReconstructBytes(input, options);
  const size_t available = options.memory_limit_bytes ? options.memory_limit_bytes : AvailableMemoryBytes();
  if (available && need > available)
    Fail(src, ": ", options.levels, " levels at branching ", options.branching, " (a ",
         LevelResolution(options.branching, options.levels - 1), "^3 grid at the finest level) need about ",
         Gigabytes(need), " of memory, but only ", Gigabytes(available), " is available; use fewer --levels");
}

Volume Reconstruct(const ReconstructInput& input, const ReconstructOptions& requested, Progress* progress,
                   ReconstructStats* stats) {
  using Clock = std::chrono::steady_clock;
  requested.Check();
  const ReconstructOptions options = ResolveLevels(input, requested);
  if (requested.auto_levels && progress)
    progress->Say("reconstruct",
                  Str("--levels auto: ", options.levels, " levels (the finest texel about one photo pixel)"));
  options.Check();
  CheckReconstructInput(input, options);
  const std::optional<DeepeningRule> deepening = DeepeningFor(input, options);
  const int ceiling = deepening ? DeepeningCeiling(input, options) : options.levels;
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  Volume volume;
  arena.execute([&] {
    const size_t n_views = input.views.size();
    std::vector<MatteStats> mattes(n_views);
    tbb::parallel_for(size_t(0), n_views,
                      [&](size_t v) { mattes[v] = MatteStats(input.mattes[v], CarveThreshold8(options.carve_alpha)); });
    const GridFrame frame = RootCube(input.bounds_min, input.bounds_max, options.margin, options.branching);

    const auto solve_start = Clock::now();
    const OpacityResult solved = EstimateOpacity(frame, input.views, mattes, ceiling, options.opacity, progress,
                                                 deepening ? &*deepening : nullptr);
    const auto billboard_start = Clock::now();
    if (stats) {
      stats->solve_seconds = std::chrono::duration<double>(billboard_start - solve_start).count();
      stats->levels = solved.reports;
      for (const OpacityLevelReport& r : solved.reports) stats->ray_passes += r.rays * size_t(r.solve.iterations);
    }

    volume.origin = frame.origin;
    volume.size = frame.size;
    volume.branching = options.branching;
    volume.texels = options.texels;
    volume.levels.resize(solved.levels.size());
    for (size_t l = 0; l < solved.levels.size(); ++l) {
      volume.levels[l].resolution = frame.Resolution(int(l));
      volume.levels[l].cells = solved.levels[l].cells;
      volume.levels[l].density = solved.levels[l].density;
    }
    std::vector<Image8> white;
    if (input.foreground.empty())
      for (const Image8& m : input.mattes) white.push_back(WhiteForeground(m));
    BillboardOptions billboards = options.billboards;
    billboards.epsilon = options.opacity.tomography.epsilon;  // one optical depth for both (optical_depth.h)
    const std::vector<Image8>& foreground = input.foreground.empty() ? white : input.foreground;
    MakeBillboards(input.views, mattes, foreground, billboards, &volume, progress);
    if (stats) {
      stats->billboard_seconds = std::chrono::duration<double>(Clock::now() - billboard_start).count();
      for (const VolumeLevel& level : volume.levels)
        stats->texel_rays += level.cells.size() * input.views.size() * size_t(options.texels) * options.texels;
    }
    if (options.fit.enabled) {
      BillboardFitOptions fit = options.fit;
      fit.billboard_scale = options.billboards.scale;
      const BillboardFitReport report = FitBillboards(input.views, input.mattes, foreground, fit, &volume, progress);
      if (progress) SayFitReport(report, *progress);
      if (stats) stats->fit = report;
    }
  });
  if (progress)
    for (size_t l = 0; l < volume.levels.size(); ++l) {
      const VolumeLevel& level = volume.levels[l];
      progress->Say("reconstruct", Str("level ", l, ": ", level.cells.size(), " cells, ",
                                       level.billboards_before_pruning, " billboards before pruning, ",
                                       level.billboards.size(), " after (", PrunedPercent(level), "% pruned)"));
    }
  CheckVolume(volume, input.source);
  return volume;
}

}  // namespace voltree
