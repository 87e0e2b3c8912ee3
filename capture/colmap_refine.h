// Tightens a COLMAP model after mapping: drops the points that reproject far from their
// observations and bundle-adjusts what is left.
//
// COLMAP's mapper keeps an observation up to 4 px from its point's projection
// (Mapper.filter_max_reproj_error). On photos of trees the worst of those lie on leaf edges and
// where branches cross, where no 3D point stands, and they pull the cameras by a tenth of a degree
// at 512² in the eye-level ring. The threshold is relative to the model's own mean error, so that
// it means the same at any photo size.
#pragma once

#include <filesystem>

#include "core/colmap_model.h"
#include "core/progress.h"

namespace voltree {

struct ModelRefinementOptions {
  int rounds = 2;                // filter + bundle adjustment, repeated
  double max_error = 1.5;        // keep points whose error is at most this times the mapper's mean
  double min_tri_angle = 1.5;    // degrees, as the mapper's own filter
  bool keep_intrinsics = false;  // known cameras: adjust poses and points only
  void Check() const;            // throws Error naming the field
};

struct RefinedModel {
  ColmapModel model;
  std::filesystem::path folder;  // where COLMAP wrote it (binary)
  int rounds_taken = 0;
  double seconds = 0;
};

// Runs `colmap point_filtering` and `colmap bundle_adjuster` on the model in `model_folder`
// (`model` is what it holds), writing each round and its logs under `work_folder`. A round that
// would lose a photo or every point is not taken: the model before it is returned, and it says so.
RefinedModel RefineColmapModel(const std::filesystem::path& colmap, const std::filesystem::path& model_folder,
                               const ColmapModel& model, const std::filesystem::path& work_folder,
                               const ModelRefinementOptions& options, Progress& progress);

}  // namespace voltree
