// Bundle adjustment of a COLMAP model under a robust loss, after COLMAP's mapper.
//
// The mapper keeps every observation within 4 px of its point and adjusts them all by least
// squares. On photos of trees the worst of them lie on leaf edges and where branches cross, where
// no 3D point stands, and at 512² they pull the eye-level ring's cameras by up to 0.19 degrees. A
// Cauchy loss of about twice SIFT's localization noise (0.3 px) lets the good observations decide:
// on five mapper models of the oak (24 photos at 512², realistic backdrop) the worst camera went
// from 0.11-0.19 to 0.05-0.07 degrees, where dropping the far observations and adjusting again by
// least squares left 0.07-0.10.
#pragma once

#include <cstddef>
#include <string>

#include "core/colmap_model.h"

namespace voltree {

struct RobustAdjustOptions {
  double loss_scale = 0.5;  // pixels: the Cauchy loss's scale (0: no adjustment, keep the model)
  // Pixels: afterwards an observation further than this from its point's projection is dropped,
  // and so is a point left with fewer than two observations.
  double max_error = 2;
  int max_iterations = 100;
  bool keep_intrinsics = false;  // known cameras: adjust poses and points only
  int threads = 0;               // 0: every hardware thread
  void Check() const;            // throws Error naming the field
};

struct RobustAdjustReport {
  bool adjusted = false;  // false: the model is as it was, and `note` says why
  std::string note;
  int iterations = 0;
  double error_before = 0, error_after = 0;  // mean reprojection error, pixels
  size_t observations_before = 0, observations_after = 0;
  size_t points_before = 0, points_after = 0;
  double seconds = 0;
};

// Adjusts the poses, the points and (unless kept) each camera's focal length and distortion; the
// principal point stays, as in COLMAP. The first image's pose and the scale stay fixed (the gauge
// the similarity to the tree frame sets later). When the solver fails or gives a non-finite
// result, `model` is left untouched.
RobustAdjustReport AdjustBundleRobustly(ColmapModel& model, const RobustAdjustOptions& options);

}  // namespace voltree
