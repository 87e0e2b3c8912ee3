// The reconstruct stage: calibrated views + mattes + foreground colours -> a Volume (octree of
// densities with billboard textures at every level, pruned). See ARCHITECTURE.md "Reconstruct".
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/camera.h"
#include "core/image.h"
#include "core/progress.h"
#include "reconstruct/billboard_fit.h"
#include "reconstruct/billboards.h"
#include "reconstruct/opacity.h"
#include "core/volume.h"

namespace voltree {

struct ReconstructOptions {
  int levels = 7;            // level 0 = root ... levels-1 (64^3 cells for 7 levels of an octree)
  bool auto_levels = false;  // levels from the photos instead (auto_levels.h): a finest texel ~ one pixel
  // More levels than `levels`, up to as many as the photos fill (auto_levels.h), while the asset
  // they would make is predicted to fit this many bytes (0: never; `run` and `demo` pass their
  // --max-bytes unless --levels is given). A sparse tree gains a level (the third-party aspen at
  // 512²: 8 levels, held-out alpha PSNR +1.6 dB); a dense one's next level would not fit.
  uint64_t deepen_within_bytes = 0;
  int branching = 2;              // 2: octree, 3: tri-grid (Reche 2004)
  int texels = 4;                 // billboards are texels x texels (8 for Reche 2004)
  double margin = 0.05;           // root cube = bounds' cube grown by this fraction of its edge per side
  double carve_alpha = 0.02;      // pixels at or below this alpha are empty for carving
  int threads = 0;                // 0: all cores
  size_t memory_limit_bytes = 0;  // 0: the memory available now (/proc/meminfo)
  OpacityOptions opacity;         // the tomography: solver, ray sampling, refinement
  BillboardOptions billboards;    // texel colours and pruning; their epsilon is the tomography's
  BillboardFitOptions fit;        // billboards fitted to the photos; their scale is billboards.scale

  void Check() const;  // throws OptionError naming the field
  nlohmann::json ToJson() const;
};

struct ReconstructInput {
  std::vector<View> views;
  std::vector<Image8> mattes;      // per view, 1 channel, the camera's size
  std::vector<Image8> foreground;  // per view, premultiplied RGBA, the camera's size
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bounds_max = Eigen::Vector3d::Ones();
  std::string source = "memory";  // names the inputs in error messages, e.g. the workspace
};

// Estimated peak bytes of a reconstruction, for the memory check.
size_t EstimateReconstructBytes(const ReconstructInput& input, const ReconstructOptions& options);
// Bytes available to this process now (MemAvailable), or 0 when unknown.
size_t AvailableMemoryBytes();

// Throws Error (naming the view or matte) for invalid cameras, views that do not see the bounds,
// mattes of the wrong size, all-empty mattes, inverted/unmatted mattes, too little memory.
void CheckReconstructInput(const ReconstructInput& input, const ReconstructOptions& options);

// Timings and work counts, for benchmarks.
struct ReconstructStats {
  double solve_seconds = 0, billboard_seconds = 0;
  size_t ray_passes = 0;  // sum over levels of rays x solver iterations
  size_t texel_rays = 0;  // billboard texel rays traced
  std::vector<OpacityLevelReport> levels;
  BillboardFitReport fit;  // empty levels when the fit is off
};

Volume Reconstruct(const ReconstructInput& input, const ReconstructOptions& options, Progress* progress,
                   ReconstructStats* stats = nullptr);

}  // namespace voltree
