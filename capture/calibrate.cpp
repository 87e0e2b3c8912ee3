#include "capture/calibrate.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "capture/calibrate_colmap.h"
#include "capture/colmap_binary.h"
#include "capture/colmap_database.h"
#include "capture/normalize.h"
#include "capture/photo_folder.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"

namespace voltree {
namespace fs = std::filesystem;

FeatureMask FeatureMaskFromName(const std::string& name) {
  if (name == "all") return FeatureMask::kAll;
  if (name == "tree") return FeatureMask::kTree;
  if (name == "near") return FeatureMask::kNear;
  Fail("unknown feature mask '", name, "' (expected all, tree or near)");
}

void CalibrateOptions::Check() const {
  const CameraModel model = CameraModelFromName(camera_model);
  if (!camera_params.empty() && int(camera_params.size()) != CameraModelParamCount(model))
    FailOption("CalibrateOptions.camera_params", "for ", camera_model, " needs ", CameraModelParamCount(model),
               " values, got ", camera_params.size());
  if (max_image_size < 64) FailOption("CalibrateOptions.max_image_size", "must be at least 64, got ", max_image_size);
  if (max_features < 64) FailOption("CalibrateOptions.max_features", "must be at least 64, got ", max_features);
  if (min_pose_inliers < 6)
    FailOption("CalibrateOptions.min_pose_inliers", "must be at least 6, got ", min_pose_inliers);
  if (matcher != "exhaustive" && matcher != "sequential")
    FailOption("CalibrateOptions.matcher", "must be exhaustive or sequential, got '", matcher, "'");
  adjust.Check();
  if (!(min_registered >= 0 && min_registered <= 1))
    FailOption("CalibrateOptions.min_registered", "must be in [0, 1], got ", min_registered);
  if (!(near_band > 0 && near_band < 1)) FailOption("CalibrateOptions.near_band", "must be in (0, 1), got ", near_band);
  if (up && !(up->norm() > 0 && up->allFinite())) FailOption("CalibrateOptions.up", "must be a non-zero direction");
  if (height_metres && !(*height_metres > 0))
    FailOption("CalibrateOptions.height_metres", "must be positive, got ", *height_metres);
  if (!import_model.empty() && !known_cameras.empty())
    FailOption("CalibrateOptions.import_model", "and --known-cameras exclude each other");
  hull.Check();
}

namespace {

struct Bounds {
  Eigen::Vector3d min, max, base;
  std::string source;
};

// Cameras that all stand at one point see the tree from one place: no up axis, no hull, no
// tomography. Such a model (a copied pose, a tripod pano) is refused, not normalized into NaN.
void CheckCamerasAreApart(const ColmapModel& model, const fs::path& source) {
  if (model.images.size() < 2) return;
  const Eigen::Vector3d first = model.images.begin()->second.pose.Center();
  double spread = 0;
  for (const auto& [id, image] : model.images) spread = std::max(spread, (image.pose.Center() - first).norm());
  if (!(spread > 1e-9 * std::max(1.0, first.norm())))
    Fail(source.string(), ": all ", model.images.size(), " cameras stand at one position (", first.transpose(),
         "); expected photos taken from around the tree");
}

// The tree's bounds in a Z-up model: the visual hull of DIR/mattes/ when every registered photo
// has a matte; else the sparse points near where the cameras look (5th..95th percentiles).
Bounds FindBounds(const fs::path& workspace, const ColmapModel& model, const HullOptions& hull_options,
                  Progress& progress) {
  const std::vector<View> views = model.Views();
  std::vector<Image8> mattes;
  std::string lacking;  // the first camera without a matte, said in the messages below
  for (const View& view : views) {
    const fs::path matte = workspace / "mattes" / (fs::path(view.name).stem().string() + ".png");
    if (!fs::is_regular_file(matte)) {
      const bool has_photo = fs::is_regular_file(workspace / "images" / view.name);
      lacking = Str("the model's camera for ", view.name, " has no matte ", matte.string(),
                    has_photo ? "" : Str(" and no photo in ", (workspace / "images").string()));
      break;
    }
    mattes.push_back(ReadImage8(matte, 1));
  }
  if (mattes.size() == views.size()) {
    const VisualHull hull = CarveVisualHullAuto(views, mattes, hull_options);
    progress.Say("calibrate", Str("visual hull: ", hull.voxels, " voxels of ", hull.voxel_size));
    Bounds bounds{hull.bounds_min, hull.bounds_max, hull.base, "visual hull"};
    // The hull reaches below the trunk base (measured 4% of the height on studio sets); the ground
    // points around the tree, when there are enough, say where the base really is.
    const double height = hull.bounds_max.z() - hull.bounds_min.z();
    std::vector<Eigen::Vector3d> points;
    for (const auto& [id, point] : model.points) points.push_back(point.position);
    const std::optional<double> ground =
        EstimateGroundHeight(points, hull.base.head<2>(), (hull.bounds_max - hull.bounds_min).head<2>().norm(),
                             hull.bounds_min.z() - 0.05 * height, hull.bounds_min.z() + 0.2 * height, 0.01 * height);
    if (ground && *ground > hull.base.z()) {
      progress.Say("calibrate", Str("ground found ", *ground - hull.base.z(), " above the hull's base; base moved up"));
      bounds.base.z() = *ground;
      bounds.min.z() = *ground;
      bounds.source = "visual hull and ground points";
    }
    return bounds;
  }
  progress.Say("calibrate", Str(lacking, "; bounds from the sparse points"));
  const Eigen::Vector3d target = LookAtPoint(views);
  double distance = 0;
  for (const View& view : views) distance += (view.pose.Center() - target).norm();
  distance /= double(views.size());
  std::vector<double> axes[3];
  for (const auto& [id, point] : model.points)
    if ((point.position - target).norm() < 0.5 * distance)
      for (int k = 0; k < 3; ++k) axes[k].push_back(point.position[k]);
  if (axes[0].size() < 10)
    Fail("cannot bound the tree: ", lacking,
         ", and too few sparse points are near it; expected a matte for every "
         "camera of the model (run 'voltree matte', or remove the cameras of photos you left out)");
  Bounds bounds;
  for (int k = 0; k < 3; ++k) {
    std::sort(axes[k].begin(), axes[k].end());
    bounds.min[k] = axes[k][axes[k].size() * 5 / 100];
    bounds.max[k] = axes[k][axes[k].size() * 95 / 100];
  }
  bounds.base = {0.5 * (bounds.min.x() + bounds.max.x()), 0.5 * (bounds.min.y() + bounds.max.y()), bounds.min.z()};
  bounds.source = "sparse points";
  return bounds;
}

// One line per photo that did not register, with the reason COLMAP's database gives when there is
// one (features found, matches verified); the first 20 photos.
std::string DescribeUnregistered(const std::vector<std::string>& names, const fs::path& database,
                                 const CalibrateOptions& options) {
  std::map<std::string, PhotoMatches> matches;
  if (!database.empty() && fs::is_regular_file(database)) try {
      for (PhotoMatches& photo : ReadPhotoMatches(database)) matches[photo.name] = std::move(photo);
    } catch (const Error& error) {  // the names still help without the reasons
      return Str("  ", names.size(), " photos (", error.what(), ")");
    }
  std::string lines;
  for (size_t i = 0; i < names.size() && i < 20; ++i) {
    const auto photo = matches.find(names[i]);
    lines += Str("  ", names[i],
                 photo == matches.end() ? std::string(database.empty() ? "" : ": not in COLMAP's database")
                                        : ": " + WhyNotRegistered(photo->second, options.min_pose_inliers),
                 "\n");
  }
  if (names.size() > 20) lines += Str("  ... (", names.size(), " in all)\n");
  lines.pop_back();
  return lines;
}

void WriteSceneJson(const fs::path& path, const CalibrateReport& report, const std::string& source) {
  auto vector = [](const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  const nlohmann::json scene = {{"frame", "tree"},
                                {"up", {0, 0, 1}},
                                {"units", report.units},
                                {"bounds_min", vector(report.bounds_min)},
                                {"bounds_max", vector(report.bounds_max)},
                                {"source", source}};
  WriteFileAtomic(path, scene.dump(2) + "\n");
}

}  // namespace

void UpdateBoundsFromMattes(const fs::path& workspace, const HullOptions& hull, Progress& progress) {
  hull.Check();
  const fs::path scene_path = workspace / "scene.json";
  CalibrateReport report;
  report.units = "reconstruction";
  std::string source = "colmap";
  if (fs::exists(scene_path)) {
    const nlohmann::json scene = nlohmann::json::parse(ReadFile(scene_path));
    report.units = scene.value("units", report.units);
    source = scene.value("source", source);
  }
  // The studio's bounds are measured on the tree itself; a visual hull could only loosen them (it
  // reaches below the ground, where no photo sees).
  if (source == "studio") {
    progress.Say("calibrate", Str("the bounds in ", scene_path.string(), " are the studio's true ones; kept"));
    return;
  }
  const ColmapModel model = ReadColmapModel(workspace / "sparse");
  const Bounds bounds = FindBounds(workspace, model, hull, progress);
  if (bounds.source == "sparse points") Fail((workspace / "mattes").string(), ": not every photo has a matte");
  report.bounds_min = bounds.min;
  report.bounds_max = bounds.max;
  WriteSceneJson(scene_path, report, source);
  progress.Say("calibrate", Str("bounds from the mattes' ", bounds.source, " written to ", scene_path.string()));
}

CalibrateReport CalibrateWorkspace(const fs::path& workspace, const CalibrateOptions& options, Progress& progress) {
  options.Check();
  CalibrateReport report;
  const std::vector<fs::path> photos = ListPhotos(workspace / "images");
  const std::vector<std::string> images = PhotoNames(photos);
  report.images = int(images.size());
  const std::vector<fs::path> turned = CheckPhotoSizes(photos);
  const fs::path colmap_folder = workspace / "colmap";
  const bool run_colmap = options.import_model.empty() && options.known_cameras.empty();
  if (run_colmap && fs::exists(colmap_folder / "database.db") && !options.force)
    Fail((colmap_folder / "database.db").string(), " already exists; pass --force to calibrate again");
  // Fails now, before any work, when sparse/ holds a model and --force is missing.
  StagedDirectory sparse(workspace / "sparse", options.force);

  ColmapModel model;
  std::string source = "colmap";
  if (!options.known_cameras.empty()) {
    model = ReadColmapModel(options.known_cameras);
    source = "known-cameras";
  } else if (!options.import_model.empty()) {
    model = ReadColmapModel(options.import_model);
  } else {
    std::error_code ignored;
    fs::remove(colmap_folder / "database.db", ignored);
    fs::remove_all(colmap_folder / "sparse", ignored);
    fs::remove_all(colmap_folder / "masks", ignored);
    // COLMAP's one shared camera takes one image size: photos turned to portrait get their own.
    if (!turned.empty())
      progress.Say("calibrate", Str(turned.size(), " of ", photos.size(), " photos are turned by 90 degrees (",
                                    turned.front().filename().string(),
                                    ", ...): COLMAP solves a camera for each photo instead of one for all"));
    const ColmapSfmResult sfm = RunColmapSfm(workspace, colmap_folder, options, turned.empty(), progress);
    model = sfm.model;
    report.models_found = sfm.models_found;
    report.stage_seconds = sfm.stage_seconds;
  }
  model.Check();
  CheckCamerasAreApart(model, run_colmap                      ? colmap_folder
                              : options.known_cameras.empty() ? options.import_model
                                                              : options.known_cameras);

  // Registration: every photo should have a camera.
  std::vector<std::string> registered;
  for (const auto& [id, image] : model.images) registered.push_back(image.name);
  std::sort(registered.begin(), registered.end());
  for (const std::string& name : images)
    if (!std::binary_search(registered.begin(), registered.end(), name)) report.unregistered.push_back(name);
  report.registered = int(images.size() - report.unregistered.size());
  if (report.registered != int(model.images.size()))
    progress.Say("calibrate", Str("the model has ", model.images.size() - report.registered,
                                  " cameras for photos not in images/; they are kept"));
  const fs::path database = run_colmap ? colmap_folder / "database.db" : fs::path();
  auto list = [](const std::vector<std::string>& names) {
    std::string joined;
    for (size_t i = 0; i < names.size() && i < 20; ++i) joined += (i ? ", " : "") + names[i];
    return names.size() > 20 ? joined + Str(", ... (", names.size(), " in all)") : joined;
  };
  if (report.registered < 3 && !run_colmap) {  // COLMAP never ran: the names are what is wrong
    const fs::path& given = options.known_cameras.empty() ? options.import_model : options.known_cameras;
    Fail("only ", report.registered, " of ", images.size(), " photos have a camera in ", given.string(),
         " (at least 3 needed): its images are ", list(registered), " but ", (workspace / "images").string(), " holds ",
         list(images), "; expected the model's image names to be the photos' file names");
  }
  if (report.registered < 3)
    Fail("only ", report.registered, " of ", images.size(), " photos registered (at least 3 needed); ",
         "the photos need more overlap or texture. Logs in ", colmap_folder.string());
  if (report.registered < options.min_registered * report.images)
    Fail("only ", report.registered, " of ", report.images, " photos registered (--min-registered ",
         options.min_registered, "); missing:\n", DescribeUnregistered(report.unregistered, database, options));
  if (!report.unregistered.empty())
    progress.Say("calibrate",
                 Str(report.unregistered.size(), report.unregistered.size() == 1 ? " photo" : " photos",
                     " did not register:\n", DescribeUnregistered(report.unregistered, database, options)));

  // Into the tree frame.
  if (options.known_cameras.empty()) {
    const Eigen::Vector3d up = options.up ? options.up->normalized() : EstimateUp(model.Views());
    const Similarity level{1.0, RotationToZUp(up), Eigen::Vector3d::Zero()};
    model = TransformModel(model, level);
    const Bounds bounds = FindBounds(workspace, model, options.hull, progress);
    const double height = bounds.max.z() - bounds.base.z();
    const double scale = options.height_metres ? *options.height_metres / height : 1.0;
    const Similarity to_origin{scale, Eigen::Quaterniond::Identity(), -scale * bounds.base};
    model = TransformModel(model, to_origin);
    report.bounds_min = to_origin.Apply(bounds.min);
    report.bounds_max = to_origin.Apply(bounds.max);
    report.bounds_source = bounds.source;
    report.units = options.height_metres ? "metres" : "reconstruction";
  } else {
    const Bounds bounds = FindBounds(workspace, model, options.hull, progress);
    report.bounds_min = bounds.min;
    report.bounds_max = bounds.max;
    report.bounds_source = bounds.source;
    report.units = "metres";  // known cameras are taken to be in the tree frame already
  }
  report.mean_reprojection_error = MeanReprojectionError(model);

  WriteColmapText(sparse.path(), model);
  sparse.Commit();
  WriteSceneJson(workspace / "scene.json", report, source);
  progress.Say("calibrate",
               Str(report.registered, "/", report.images, " photos registered, mean reprojection error ",
                   report.mean_reprojection_error, " px; wrote ", (workspace / "sparse").string(), " and scene.json"));
  return report;
}

}  // namespace voltree
