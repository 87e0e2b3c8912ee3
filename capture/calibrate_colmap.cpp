#include "capture/calibrate_colmap.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <opencv2/imgproc.hpp>

#include "capture/colmap_binary.h"
#include "capture/bundle_adjust.h"
#include "capture/colmap_runner.h"
#include "capture/photo_folder.h"
#include "core/error.h"
#include "core/image.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

std::string JoinNumbers(const std::vector<double>& values) {
  std::string joined;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) joined += ',';
    joined += Str(std::setprecision(17), values[i]);
  }
  return joined;
}

fs::path MattePath(const fs::path& workspace, const std::string& image) {
  return workspace / "mattes" / (fs::path(image).stem().string() + ".png");
}

}  // namespace

bool WriteFeatureMasks(const fs::path& workspace, const fs::path& mask_folder, const std::vector<std::string>& images,
                       const CalibrateOptions& options) {
  for (const std::string& image : images)
    if (!fs::is_regular_file(MattePath(workspace, image))) return false;
  fs::create_directories(mask_folder);
  for (const std::string& image : images) {
    const Image8 matte = ReadImage8(MattePath(workspace, image), 1);
    cv::Mat alpha(matte.height, matte.width, CV_8UC1, const_cast<uint8_t*>(matte.pixels.data()));
    cv::Mat mask;
    cv::threshold(alpha, mask, 0, 255, cv::THRESH_BINARY);  // any coverage counts as the tree
    // kTree keeps a small margin: features on the silhouette straddle tree and background.
    const double diagonal = std::hypot(matte.width, matte.height);
    const double band = options.mask == FeatureMask::kNear ? options.near_band : 0.01;
    const int radius = std::max(1, int(std::lround(band * diagonal)));
    cv::dilate(mask, mask, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
    Image8 out(matte.width, matte.height, 1);
    std::copy(mask.datastart, mask.dataend, out.pixels.begin());
    WriteImage(mask_folder / (image + ".png"), out);  // COLMAP's convention: a.png -> a.png.png
  }
  return true;
}

ColmapSfmResult RunColmapSfm(const fs::path& workspace, const fs::path& colmap_folder, const CalibrateOptions& options,
                             bool shared_camera, Progress& progress) {
  const fs::path colmap = FindColmap();
  const fs::path database = colmap_folder / "database.db";
  const fs::path sparse = colmap_folder / "sparse";
  const fs::path images = workspace / "images";
  fs::create_directories(sparse);
  ColmapSfmResult result;
  auto stage = [&](const std::string& name, const std::vector<std::string>& args) {
    const ChildResult run = RunColmapStage(colmap, name, args, colmap_folder / (name + ".log"));
    result.stage_seconds.emplace_back(name, run.seconds);
    progress.Say("calibrate", Str("colmap ", name, " done in ", Str(std::round(run.seconds * 10) / 10), " s"));
  };

  std::vector<std::string> extract = {"--database_path",
                                      database.string(),
                                      "--image_path",
                                      images.string(),
                                      "--ImageReader.single_camera",
                                      shared_camera ? "1" : "0",
                                      "--ImageReader.camera_model",
                                      options.camera_model,
                                      "--SiftExtraction.use_gpu",
                                      "0",
                                      "--SiftExtraction.max_image_size",
                                      Str(options.max_image_size),
                                      "--SiftExtraction.max_num_features",
                                      Str(options.max_features)};
  if (!options.camera_params.empty())
    extract.insert(extract.end(), {"--ImageReader.camera_params", JoinNumbers(options.camera_params)});
  if (options.affine_features) extract.insert(extract.end(), {"--SiftExtraction.estimate_affine_shape", "1"});
  if (options.mask != FeatureMask::kAll) {
    const fs::path masks = colmap_folder / "masks";
    if (WriteFeatureMasks(workspace, masks, PhotoNames(FindPhotos(images)), options))
      extract.insert(extract.end(), {"--ImageReader.mask_path", masks.string()});
    else
      progress.Say("calibrate", "not every photo has a matte in mattes/; extracting features everywhere");
  }
  stage("feature_extractor", extract);
  stage(options.matcher + "_matcher", {"--database_path", database.string(), "--SiftMatching.use_gpu", "0",
                                       "--SiftMatching.guided_matching", options.guided_matching ? "1" : "0"});
  std::vector<std::string> map = {"--database_path",
                                  database.string(),
                                  "--image_path",
                                  images.string(),
                                  "--output_path",
                                  sparse.string(),
                                  "--Mapper.abs_pose_min_num_inliers",
                                  Str(options.min_pose_inliers)};
  if (!options.camera_params.empty())  // known intrinsics stay as given
    map.insert(map.end(), {"--Mapper.ba_refine_focal_length", "0", "--Mapper.ba_refine_principal_point", "0",
                           "--Mapper.ba_refine_extra_params", "0"});
  // The mapper exits with an error when it could not start any model ("No good initial image
  // pair found"): say what that means for the photos instead of showing the log's tail.
  const fs::path mapper_log = colmap_folder / "mapper.log";
  const ChildResult mapper = RunChild(
      colmap,
      [&] {
        std::vector<std::string> full = {"mapper"};
        full.insert(full.end(), map.begin(), map.end());
        return full;
      }(),
      mapper_log);
  result.stage_seconds.emplace_back("mapper", mapper.seconds);
  if (!mapper.ok() && mapper.signal == 0 &&
      LogTail(mapper_log, 3).find("failed to create sparse model") != std::string::npos)
    Fail("COLMAP could not start a model: no pair of photos shares enough matched features (see ", mapper_log.string(),
         "). Neighbouring photos should overlap more (more photos, at most ~30 degrees "
         "apart around the tree, not grazing the ground), or --max-image-size/--max-features higher");
  if (!mapper.ok())
    Fail("colmap mapper ",
         mapper.signal != 0 ? Str("crashed (signal ", mapper.signal, ")")
                            : Str("failed (exit code ", mapper.exit_code, ")"),
         "; the end of its log ", mapper_log.string(), ":\n", LogTail(mapper_log, 15));
  progress.Say("calibrate", Str("colmap mapper done in ", Str(std::round(mapper.seconds * 10) / 10), " s"));

  // The mapper writes one numbered folder per connected model; keep the largest.
  std::vector<fs::path> models;
  for (const auto& entry : fs::directory_iterator(sparse))
    if (entry.is_directory() && HasColmapModel(entry.path())) models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  result.models_found = int(models.size());
  if (models.empty())
    Fail("COLMAP reconstructed nothing: too few matches between the photos (see ",
         (colmap_folder / "mapper.log").string(),
         "). More overlap between photos, or --max-image-size/--max-features "
         "higher, may help");
  size_t best_size = 0;
  for (const fs::path& folder : models) {
    ColmapModel model = ReadColmapModel(folder);
    if (model.images.size() > best_size) {
      best_size = model.images.size();
      result.model = std::move(model);
      result.model_folder = folder;
    }
  }
  if (result.models_found > 1)
    progress.Say("calibrate", Str("COLMAP made ", result.models_found, " separate models; keeping the largest, ",
                                  result.model_folder.string(), " (", best_size, " photos)"));
  RobustAdjustOptions adjust = options.adjust;
  adjust.keep_intrinsics = adjust.keep_intrinsics || !options.camera_params.empty();
  const RobustAdjustReport adjusted = AdjustBundleRobustly(result.model, adjust);
  result.stage_seconds.emplace_back("adjust", adjusted.seconds);
  if (adjusted.adjusted) {
    progress.Say("calibrate",
                 Str("robust bundle adjustment: mean error ", std::round(adjusted.error_before * 1000) / 1000, " -> ",
                     std::round(adjusted.error_after * 1000) / 1000, " px, ", adjusted.observations_after, " of ",
                     adjusted.observations_before, " observations within ", adjust.max_error, " px kept (",
                     adjusted.iterations, " iterations, ", std::round(adjusted.seconds * 10) / 10, " s)"));
    result.model_folder = colmap_folder / "adjusted";
    WriteColmapText(result.model_folder, result.model);
  } else {
    if (adjust.loss_scale > 0) progress.Say("calibrate", Str("robust bundle adjustment skipped: ", adjusted.note));
    stage("model_converter", {"--input_path", result.model_folder.string(), "--output_path",
                              result.model_folder.string(), "--output_type", "TXT"});
  }
  return result;
}

}  // namespace voltree
