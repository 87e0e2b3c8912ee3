#include "reconstruct/reconstruct_workspace.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "reconstruct/auto_levels.h"
#include "reconstruct/carve.h"
#include "reconstruct/grid.h"
#include "reconstruct/matte_stats.h"
#include "core/volume_io.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

Eigen::Vector3d ReadVector(const nlohmann::json& doc, const char* field, const std::string& file) {
  if (!doc.contains(field)) Fail(file, ": missing field '", field, "' (expected [x, y, z])");
  const nlohmann::json& j = doc[field];
  if (!j.is_array() || j.size() != 3) Fail(file, ": field '", field, "' must be [x, y, z]");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) Fail(file, ": field '", field, "' must hold 3 numbers");
    v[i] = j[i].get<double>();
  }
  if (!v.allFinite()) Fail(file, ": field '", field, "' must hold finite numbers");
  return v;
}

}  // namespace

std::optional<SceneBounds> ReadSceneBounds(const fs::path& scene_json) {
  if (!fs::exists(scene_json)) return std::nullopt;
  const std::string file = scene_json.string();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(ReadFile(scene_json));
  } catch (const nlohmann::json::exception& e) {
    Fail(file, ": not valid JSON: ", e.what());
  }
  if (!doc.is_object()) Fail(file, ": expected a JSON object");
  SceneBounds bounds{ReadVector(doc, "bounds_min", file), ReadVector(doc, "bounds_max", file)};
  if ((bounds.max - bounds.min).minCoeff() < 0 || (bounds.max - bounds.min).maxCoeff() <= 0)
    Fail(file, ": bounds_max must be >= bounds_min with a positive extent");
  return bounds;
}

SceneBounds VisualHullBounds(const std::vector<View>& views, const std::vector<Image8>& mattes,
                             const SceneBounds& initial, double carve_alpha) {
  std::vector<MatteStats> stats;
  for (const Image8& m : mattes) stats.emplace_back(m, CarveThreshold8(carve_alpha));
  const GridFrame frame = RootCube(initial.min, initial.max, 0.0, 2);
  constexpr int kLevel = 5;
  const int res = frame.Resolution(kLevel);
  std::vector<CellCoord> all;
  for (int z = 0; z < res; ++z)
    for (int y = 0; y < res; ++y)
      for (int x = 0; x < res; ++x) all.push_back({uint16_t(x), uint16_t(y), uint16_t(z)});
  const std::vector<CellCoord> kept = CarveCells(frame, kLevel, all, views, stats);
  if (kept.empty()) Fail("the visual hull of the mattes is empty: no region is seen as the tree by every view");
  const LevelCells cells(res, kept);
  SceneBounds bounds;
  for (int a = 0; a < 3; ++a) {
    bounds.min[a] = frame.origin[a] + cells.box_min()[a] * frame.CellSize(kLevel);
    bounds.max[a] = frame.origin[a] + cells.box_max()[a] * frame.CellSize(kLevel);
  }
  return bounds;
}

fs::path CompanionPath(const fs::path& dir, const char* folder, const std::string& name) {
  fs::path relative(name);
  relative.replace_extension(".png");
  return dir / folder / relative;
}

ReconstructInput LoadReconstructInput(const fs::path& dir, const ReconstructOptions& options, Progress* progress) {
  if (!fs::is_directory(dir)) Fail(dir.string(), ": no such workspace folder");
  const fs::path sparse = dir / "sparse";
  if (!fs::is_directory(sparse))
    Fail(sparse.string(), ": missing (expected a COLMAP text model: cameras.txt, images.txt, points3D.txt)");
  const ColmapModel model = ReadColmapText(sparse);
  ReconstructInput input;
  input.source = dir.string();
  input.views = model.Views();
  if (input.views.empty()) Fail((sparse / "images.txt").string(), ": no registered images");
  bool any_foreground = false;
  for (const View& view : input.views) {
    const fs::path matte_path = CompanionPath(dir, "mattes", view.name);
    if (!fs::exists(matte_path))
      Fail(matte_path.string(), ": missing matte for image '", view.name, "' (run 'voltree matte' first)");
    Image8 matte = ReadImage8(matte_path, 1);
    if (matte.width != view.camera.width || matte.height != view.camera.height)
      Fail(matte_path.string(), ": is ", matte.width, "x", matte.height, ", expected the camera's ", view.camera.width,
           "x", view.camera.height);
    // Colour source: foreground/ (premultiplied RGBA), else the photo premultiplied by the matte.
    const fs::path fg_path = CompanionPath(dir, "foreground", view.name);
    Image8 foreground;
    if (fs::exists(fg_path)) {
      foreground = ReadImage8(fg_path, 4);
      any_foreground = true;
    } else if (fs::exists(dir / "images" / view.name)) {
      const Image8 photo = ReadImage8(dir / "images" / view.name, 3);
      foreground = Image8(photo.width, photo.height, 4);
      for (int y = 0; y < photo.height && y < matte.height; ++y)
        for (int x = 0; x < photo.width && x < matte.width; ++x) {
          const int a = matte.at(x, y);
          for (int c = 0; c < 3; ++c) foreground.at(x, y, c) = uint8_t((photo.at(x, y, c) * a + 127) / 255);
          foreground.at(x, y, 3) = uint8_t(a);
        }
    }
    if (!foreground.empty() && (foreground.width != matte.width || foreground.height != matte.height))
      Fail((fs::exists(fg_path) ? fg_path : dir / "images" / view.name).string(), ": is ", foreground.width, "x",
           foreground.height, ", expected ", matte.width, "x", matte.height, " like its matte");
    if (foreground.empty()) {
      foreground = Image8(matte.width, matte.height, 4);
      for (size_t i = 0; i < matte.pixels.size(); ++i)
        for (int c = 0; c < 4; ++c) foreground.pixels[i * 4 + c] = matte.pixels[i];
    }
    input.mattes.push_back(std::move(matte));
    input.foreground.push_back(std::move(foreground));
    if (progress)
      progress->Say("reconstruct", Str("read view ", input.mattes.size(), "/", input.views.size(), ": ", view.name));
  }
  if (!any_foreground && progress)
    progress->Say("reconstruct", "no foreground/ images: texel colours come from images/ (background may bleed in)");

  if (const auto bounds = ReadSceneBounds(dir / "scene.json")) {
    input.bounds_min = bounds->min;
    input.bounds_max = bounds->max;
  } else {
    // No scene.json: start from the sparse points (or the cameras) and carve a coarse hull.
    SceneBounds initial{Eigen::Vector3d::Constant(1e300), Eigen::Vector3d::Constant(-1e300)};
    if (!model.points.empty()) {
      for (const auto& [id, point] : model.points) {
        initial.min = initial.min.cwiseMin(point.position);
        initial.max = initial.max.cwiseMax(point.position);
      }
    } else {
      for (const View& v : input.views) {
        initial.min = initial.min.cwiseMin(v.pose.Center());
        initial.max = initial.max.cwiseMax(v.pose.Center());
      }
    }
    const Eigen::Vector3d centre = 0.5 * (initial.min + initial.max);
    const double half = 0.75 * (initial.max - initial.min).maxCoeff();
    initial.min = centre - Eigen::Vector3d::Constant(half);
    initial.max = centre + Eigen::Vector3d::Constant(half);
    const SceneBounds hull = VisualHullBounds(input.views, input.mattes, initial, options.carve_alpha);
    input.bounds_min = hull.min;
    input.bounds_max = hull.max;
    if (progress)
      progress->Say("reconstruct", Str("no scene.json: bounds from a coarse visual hull [", hull.min.transpose(),
                                       "] .. [", hull.max.transpose(), "]"));
  }
  return input;
}

Volume ReconstructWorkspace(const fs::path& dir, const ReconstructWorkspaceOptions& options, Progress& progress) {
  const ReconstructOptions& reconstruct = options.reconstruct;
  reconstruct.Check();
  const fs::path out = dir / "volume";
  CheckCanReplaceFolder(out, options.force);
  const ReconstructInput input = LoadReconstructInput(dir, reconstruct, &progress);
  Volume volume = Reconstruct(input, reconstruct, &progress);
  nlohmann::json recorded = ResolveLevels(input, reconstruct).ToJson();
  if (reconstruct.auto_levels) recorded["levels_auto"] = true;
  recorded["levels"] = volume.levels.size();  // deepened, or as asked
  WriteVolume(out, volume, {{"stage", "reconstruct"}, {"options", recorded}}, options.force);
  progress.Say("reconstruct", Str("wrote ", out.string()));
  return volume;
}

}  // namespace voltree
