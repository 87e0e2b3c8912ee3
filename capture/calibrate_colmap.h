// The COLMAP part of calibration: features, matches, mapping, and picking the largest model.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "capture/calibrate.h"

namespace voltree {

struct ColmapSfmResult {
  ColmapModel model;  // the largest model COLMAP produced
  std::filesystem::path model_folder;
  int models_found = 0;
  std::vector<std::pair<std::string, double>> stage_seconds;
};

// Runs feature_extractor, the matcher, mapper and model_converter on DIR/images with the database,
// masks and logs in `colmap_folder`. `shared_camera`: one camera for all photos (they share one
// size), else one per photo. Throws Error when COLMAP fails or reconstructs nothing.
ColmapSfmResult RunColmapSfm(const std::filesystem::path& workspace, const std::filesystem::path& colmap_folder,
                             const CalibrateOptions& options, bool shared_camera, Progress& progress);

// Writes COLMAP masks (DIR/colmap/masks/<image name>.png, 0 = no features) from DIR/mattes/.
// Returns false (writing nothing) when a photo has no matte.
bool WriteFeatureMasks(const std::filesystem::path& workspace, const std::filesystem::path& mask_folder,
                       const std::vector<std::string>& images, const CalibrateOptions& options);

}  // namespace voltree
