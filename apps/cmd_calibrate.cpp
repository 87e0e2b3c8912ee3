// voltree calibrate DIR: cameras for a capture workspace (COLMAP, or an imported/known model),
// normalized into the tree frame: DIR/sparse/ and DIR/scene.json.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "capture/calibrate.h"
#include "core/error.h"
#include "core/progress.h"

namespace voltree::app {

void AddCalibrateCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "calibrate",
      "Find the cameras of DIR/images/ with COLMAP (feature_extractor, matcher, mapper), check that the photos "
      "registered, and write them in the tree frame (+Z up, origin at the trunk base) to DIR/sparse/ and "
      "DIR/scene.json; COLMAP's database, logs and raw model stay in DIR/colmap/");
  struct Arguments {
    std::string dir;
    CalibrateOptions options;
    std::string mask = "all";
    std::vector<double> up;
    double height = 0;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  CalibrateOptions& o = args->options;
  command->add_option("DIR", args->dir, "Capture workspace (with images/, optionally mattes/)")->required();
  command->add_option("--camera-model", o.camera_model,
                      "COLMAP camera model shared by all photos: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV")
      ->capture_default_str();
  command->add_option("--camera-params", o.camera_params,
                      "Known intrinsics in COLMAP's order, comma separated (e.g. PINHOLE: fx,fy,cx,cy); kept fixed")
      ->delimiter(',');
  command->add_option("--max-image-size", o.max_image_size, "Longest side for feature extraction (pixels)")
      ->capture_default_str();
  command->add_option("--max-features", o.max_features, "SIFT features per photo at most")->capture_default_str();
  command->add_option("--matcher", o.matcher, "exhaustive, or sequential for photos taken in order along a walk")
      ->capture_default_str();
  command->add_option("--min-registered", o.min_registered, "Fraction of the photos that must get a camera")
      ->capture_default_str();
  command->add_option("--mask", args->mask,
                      "Where features may come from when DIR/mattes/ exists: all (default; ground and surroundings "
                      "help), tree (the tree only), near (the tree and a band around it)")
      ->capture_default_str();
  command->add_option("--up", args->up, "World up direction x,y,z in COLMAP's frame (default: from the cameras)")
      ->delimiter(',')
      ->expected(3);
  command->add_option("--height", args->height, "Tree height in metres: scale the scene to metres");
  command->add_option("--import", o.import_model,
                      "Use this existing COLMAP model (text or binary) instead of running COLMAP; it is normalized")
      ->check(CLI::ExistingDirectory);
  command->add_option("--known-cameras", o.known_cameras,
                      "Use this COLMAP model (text or binary) as is: its cameras are already in the tree frame, metres")
      ->check(CLI::ExistingDirectory);
  command->add_option("--hull-resolution", o.hull.resolution, "Voxels along the visual hull's longest side")
      ->capture_default_str();
  command->add_flag("!--no-affine", o.affine_features,
                    "Plain SIFT instead of affine-covariant SIFT (faster; photos from low and high rings then "
                    "rarely match)");
  command->add_flag("!--no-guided", o.guided_matching, "No guided matching (re-matching under the found geometry)");
  command->add_flag("--force", o.force, "Replace DIR/sparse, DIR/scene.json and COLMAP's database");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    CalibrateOptions options = args->options;
    options.mask = FeatureMaskFromName(args->mask);
    if (!args->up.empty()) options.up = Eigen::Vector3d(args->up[0], args->up[1], args->up[2]);
    if (args->height != 0) options.height_metres = args->height;
    Progress progress(args->quiet);
    const CalibrateReport report = Calibrate(args->dir, options, progress);
    std::printf("registered %d/%d photos, mean reprojection error %.3f px, bounds (%s, %s) from the %s\n",
                report.registered, report.images, report.mean_reprojection_error,
                Str(report.bounds_min.transpose()).c_str(), Str(report.bounds_max.transpose()).c_str(),
                report.bounds_source.c_str());
  });
}

}  // namespace voltree::app
