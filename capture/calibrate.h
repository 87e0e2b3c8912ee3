// `voltree calibrate`: cameras for a capture workspace. Runs COLMAP (or imports a model), checks
// that enough photos registered, normalizes the scene into the tree frame and writes DIR/sparse/
// and DIR/scene.json. COLMAP's raw output stays in DIR/colmap/.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "capture/bundle_adjust.h"
#include "capture/normalize_hull.h"
#include "core/colmap_model.h"
#include "core/progress.h"

namespace voltree {

// Which pixels COLMAP may take features from, when DIR/mattes/ exists.
//   kAll:  every pixel. The ground and the surroundings are rigid and well textured, the tree moves
//          in the wind and repeats itself; on synthetic sets they register best (see bench/calibrate).
//   kTree: the tree only (the matte, dilated a little), as ARCHITECTURE suggests against a busy,
//          changing background (people, traffic).
//   kNear: the tree and a band around it (the ground at its base), not the distant background.
enum class FeatureMask { kAll, kTree, kNear };
FeatureMask FeatureMaskFromName(const std::string& name);  // "all", "tree", "near"; Error otherwise

struct CalibrateOptions {
  std::string camera_model = "SIMPLE_RADIAL";  // COLMAP's model for the shared camera
  std::vector<double> camera_params;           // known intrinsics (COLMAP order): kept fixed
  int max_image_size = 1600;                   // --SiftExtraction.max_image_size
  int max_features = 8192;                     // --SiftExtraction.max_num_features
  std::string matcher = "exhaustive";          // or "sequential" for photos taken in a walk
  // Affine-covariant SIFT (--SiftExtraction.estimate_affine_shape) and guided matching: the ground
  // seen at 5 degrees and at 35 degrees differs by a strong affine squash, which plain SIFT does
  // not match. Without them the eye-level ring of a studio set matched no photo of the upper ring
  // and none of its 12 photos registered (oak, 24 views at 384²); with them 240-270 verified
  // matches per low photo and 24/24 registered. Affine alone gives ~50 matches and no initial pair:
  // guided matching (re-matching under the estimated geometry) supplies the rest.
  bool affine_features = true;
  bool guided_matching = true;
  // --Mapper.abs_pose_min_num_inliers (COLMAP's default 30): a photo registers with fewer 2D-3D
  // inliers. At 256² a 5-degree photo sometimes had fewer than 30 and stayed out (23 of 24, one
  // run in three of the photos-alone test; COLMAP's threads make runs differ).
  int min_pose_inliers = 15;
  // After mapping, bundle adjustment under a robust loss (capture/bundle_adjust.h).
  RobustAdjustOptions adjust;
  double min_registered = 0.8;  // fraction of the photos that must register
  FeatureMask mask = FeatureMask::kAll;
  double near_band = 0.15;              // kNear: band width as a fraction of the image diagonal
  std::optional<Eigen::Vector3d> up;    // world up in COLMAP's frame; default from the cameras
  std::optional<double> height_metres;  // tree height: scale to metres
  std::filesystem::path import_model;   // an existing COLMAP model (text or binary), normalized
  std::filesystem::path known_cameras;  // a model already in the tree frame, taken as is
  HullOptions hull;
  bool force = false;
  void Check() const;  // throws Error
};

struct CalibrateReport {
  int images = 0;  // photos in DIR/images
  int registered = 0;
  std::vector<std::string> unregistered;
  int models_found = 1;                                       // COLMAP models; the largest is kept
  double mean_reprojection_error = 0;                         // pixels, over all observations
  std::vector<std::pair<std::string, double>> stage_seconds;  // COLMAP stages
  std::string bounds_source;                                  // "visual hull", "sparse points"
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero(), bounds_max = Eigen::Vector3d::Zero();
  std::string units;  // "metres" or "reconstruction"
};

CalibrateReport CalibrateWorkspace(const std::filesystem::path& workspace, const CalibrateOptions& options,
                                   Progress& progress);

// Recomputes the tree's bounds in DIR/scene.json from DIR/mattes/ and the cameras in DIR/sparse/
// (already in the tree frame, kept as they are): for mattes made after calibration. The studio's
// bounds (scene.json's source "studio") are true and are kept. Throws Error when the mattes'
// visual hull is empty.
void UpdateBoundsFromMattes(const std::filesystem::path& workspace, const HullOptions& hull, Progress& progress);

}  // namespace voltree
