// Reconstruct benchmark: time, peak memory, rays per second, 1 vs 2 threads, octree vs tri-grid.
// Each configuration runs in a forked child so that ru_maxrss is its own peak.
//   voltree-bench-reconstruct [--workspace DIR] [--levels 7] [--trigrid-levels 5] [--threads 1,2] [--no-fit]
// Without --workspace it uses a synthetic phantom (24 views x --size^2, leafy blobs on a 64^3 grid).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "reconstruct/dda.h"
#include "reconstruct/reconstruct.h"
#include "reconstruct/reconstruct_workspace.h"
#include "reconstruct/sart.h"

namespace {
using namespace voltree;

struct Row {
  double load_s = 0, solve_s = 0, billboard_s = 0, fit_s = 0, total_s = 0;
  double ray_passes = 0, texel_rays = 0;
  double finest_cells = 0, before = 0, after = 0;
  int ok = 0;
  char error[256] = {0};
};

ReconstructInput PhantomInput(int size) {
  ReconstructInput input;
  const int res = 64;
  std::vector<double> sigma(size_t(res) * res * res, 0.0);
  for (int z = 0; z < res; ++z)
    for (int y = 0; y < res; ++y)
      for (int x = 0; x < res; ++x) {
        const Eigen::Vector3d c((x + 0.5) / res, (y + 0.5) / res, (z + 0.5) / res);
        const double s = 30 * std::exp(-(c - Eigen::Vector3d(0.4, 0.45, 0.55)).squaredNorm() / (2 * 0.12 * 0.12)) +
                         20 * std::exp(-(c - Eigen::Vector3d(0.62, 0.58, 0.4)).squaredNorm() / (2 * 0.1 * 0.1));
        // Leafy: a sparse checker of dense cells inside the blobs.
        sigma[(size_t(z) * res + y) * res + x] = ((x * 7 + y * 13 + z * 5) % 3 == 0 && s > 2) ? s : 0.0;
      }
  const GridWindow window{Eigen::Vector3d::Zero(), 1.0 / res, {0, 0, 0}, {res, res, res}};
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (int i = 0; i < 24; ++i) {
    const double azimuth = 2 * M_PI * i / 24, elevation = (i % 2 ? 20.0 : 5.0) * M_PI / 180;
    View view;
    view.name = "view_" + std::to_string(i) + ".png";
    view.camera = Camera::Pinhole(size, size, 1.45 * size, 1.45 * size, 0.5 * size, 0.5 * size);
    view.pose =
        Pose::LookAt(centre + 3.0 * Eigen::Vector3d(std::cos(azimuth) * std::cos(elevation),
                                                    std::sin(azimuth) * std::cos(elevation), std::sin(elevation)),
                     centre, Eigen::Vector3d::UnitZ());
    Image8 matte(size, size, 1), fg(size, size, 4);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        double depth = 0;
        TraverseGrid(window, Ray{view.pose.Center(), view.PixelRay({x + 0.5, y + 0.5})}, 0, 1e30,
                     [&](int cx, int cy, int cz, double l, double) {
                       depth += sigma[(size_t(cz) * res + cy) * res + cx] * l;
                       return true;
                     });
        const uint8_t a = uint8_t(std::lround(255 * (1 - std::exp(-depth))));
        matte.at(x, y) = a;
        fg.at(x, y, 0) = uint8_t(a * 60 / 255);
        fg.at(x, y, 1) = uint8_t(a * 140 / 255);
        fg.at(x, y, 2) = uint8_t(a * 50 / 255);
        fg.at(x, y, 3) = a;
      }
    input.views.push_back(view);
    input.mattes.push_back(matte);
    input.foreground.push_back(fg);
  }
  input.bounds_min = Eigen::Vector3d::Constant(0.1);
  input.bounds_max = Eigen::Vector3d::Constant(0.9);
  input.source = "phantom";
  return input;
}

Row RunOne(const std::string& workspace, ReconstructOptions options, int size) {
  Row row;
  try {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    Progress quiet(true);
    const ReconstructInput input =
        workspace.empty() ? PhantomInput(size) : LoadReconstructInput(workspace, options, &quiet);
    const auto loaded = Clock::now();
    ReconstructStats stats;
    const Volume volume = Reconstruct(input, options, &quiet, &stats);
    row.load_s = std::chrono::duration<double>(loaded - start).count();
    row.total_s = std::chrono::duration<double>(Clock::now() - loaded).count();
    row.solve_s = stats.solve_seconds;
    row.billboard_s = stats.billboard_seconds;
    row.fit_s = stats.fit.seconds;
    row.ray_passes = double(stats.ray_passes);
    row.texel_rays = double(stats.texel_rays);
    row.finest_cells = double(volume.levels.back().cells.size());
    for (const VolumeLevel& level : volume.levels) {
      row.before += double(level.billboards_before_pruning);
      row.after += double(level.billboards.size());
    }
    row.ok = 1;
  } catch (const std::exception& e) {
    std::snprintf(row.error, sizeof(row.error), "%s", e.what());
  }
  return row;
}

// Runs one configuration in a child process; returns its row and its peak resident memory.
Row RunForked(const std::string& workspace, const ReconstructOptions& options, int size, double* peak_mb) {
  int fds[2];
  if (pipe(fds) != 0) voltree::Fail("pipe failed");
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const Row row = RunOne(workspace, options, size);
    if (write(fds[1], &row, sizeof(row)) != ssize_t(sizeof(row))) _exit(2);
    _exit(0);
  }
  close(fds[1]);
  Row row;
  if (read(fds[0], &row, sizeof(row)) != ssize_t(sizeof(row)))
    std::snprintf(row.error, sizeof(row.error), "child died");
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  *peak_mb = usage.ru_maxrss / 1024.0;  // kilobytes on Linux
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Benchmark of voltree reconstruct: one forked run per configuration"};
  std::string workspace;
  int levels = 7, trigrid_levels = 5, iterations = SartOptions{}.iterations, texels = 4, size = 256;
  std::vector<int> threads = {1, 2};
  app.add_option("--workspace", workspace, "Capture workspace (default: a synthetic phantom)");
  app.add_option("--levels", levels, "Octree levels")->capture_default_str();
  app.add_option("--trigrid-levels", trigrid_levels, "Tri-grid levels (0: skip)")->capture_default_str();
  app.add_option("--iterations", iterations, "SART iterations per level")->capture_default_str();
  app.add_option("--size", size, "Phantom image size (pixels per side)")->capture_default_str();
  app.add_option("--texels", texels, "Texels per billboard side")->capture_default_str();
  app.add_option("--threads", threads, "Thread counts to compare")->delimiter(',');
  bool no_fit = false;
  app.add_flag("--no-fit", no_fit, "Leave out the billboard fit (the tomography's billboards as they are)");
  CLI11_PARSE(app, argc, argv);

  if (workspace.empty())
    std::printf("input: synthetic phantom, 24 views x %d^2\n", size);
  else
    std::printf("input: %s\n", workspace.c_str());
  std::printf("%-9s %6s %7s %7s %8s %8s %7s %8s %9s %12s %12s %9s %11s %11s %7s\n", "grid", "levels", "threads",
              "load_s", "solve_s", "bboard_s", "fit_s", "total_s", "peak_MB", "ray_passes/s", "texel_rays/s", "cells",
              "bb_before", "bb_after", "pruned");
  struct Config {
    int branching, levels;
  };
  std::vector<Config> configs = {{2, levels}};
  if (trigrid_levels > 0) configs.push_back({3, trigrid_levels});
  for (const Config& config : configs)
    for (int t : threads) {
      ReconstructOptions options;
      options.branching = config.branching;
      options.levels = config.levels;
      options.threads = t;
      options.opacity.sart.iterations = iterations;
      options.texels = texels;
      options.fit.enabled = !no_fit;
      double peak_mb = 0;
      const Row row = RunForked(workspace, options, size, &peak_mb);
      if (!row.ok) {
        std::printf("%-9s %6d %7d  error: %s\n", config.branching == 2 ? "octree" : "tri-grid", config.levels, t,
                    row.error);
        continue;
      }
      std::printf("%-9s %6d %7d %7.2f %8.2f %8.2f %7.2f %8.2f %9.0f %12.3g %12.3g %9.0f %11.0f %11.0f %6.1f%%\n",
                  config.branching == 2 ? "octree" : "tri-grid", config.levels, t, row.load_s, row.solve_s,
                  row.billboard_s, row.fit_s, row.total_s, peak_mb, row.ray_passes / std::max(row.solve_s, 1e-9),
                  row.texel_rays / std::max(row.billboard_s, 1e-9), row.finest_cells, row.before, row.after,
                  100.0 * (row.before - row.after) / std::max(row.before, 1.0));
      std::fflush(stdout);
    }
  return 0;
}
