#include "pipeline/evaluation_truth.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "capture/calibrate_accuracy.h"
#include "core/colmap_model.h"
#include "core/error.h"
#include "core/image_resample.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// images/a/b.jpg -> FOLDER/a/b.png: companions are PNG with the photo's relative stem.
fs::path Companion(const fs::path& workspace, const char* folder, const std::string& name) {
  fs::path relative(name);
  relative.replace_extension(".png");
  return workspace / folder / relative;
}

std::vector<View> ModelViews(const fs::path& sparse) {
  if (!fs::is_directory(sparse))
    Fail(sparse.string(), ": missing (expected a COLMAP text model: cameras.txt, images.txt)");
  std::vector<View> views = ReadColmapText(sparse).Views();
  if (views.empty()) Fail((sparse / "images.txt").string(), ": no registered images");
  return views;
}

void CheckSize(const Image8& image, const TruthView& view, const fs::path& file) {
  const int width = view.photo_width > 0 ? view.photo_width : view.camera.camera.width;
  const int height = view.photo_height > 0 ? view.photo_height : view.camera.camera.height;
  if (image.width != width || image.height != height)
    Fail(file.string(), ": is ", image.width, "x", image.height, ", expected the camera's ", width, "x", height,
         " (view '", view.camera.name, "')");
}

// At the camera's size: the photo's own, or area-resampled to a camera seen from farther.
Image8 AtCameraSize(Image8 rgba, const TruthView& view) {
  if (rgba.width == view.camera.camera.width && rgba.height == view.camera.camera.height) return rgba;
  return AreaResampleRgba(rgba, view.premultiplied, view.camera.camera.width, view.camera.camera.height);
}

}  // namespace

Image8 LoadTruthImage(const TruthView& view) {
  if (!fs::exists(view.colour)) Fail(view.colour.string(), ": missing truth image for view '", view.camera.name, "'");
  Image8 rgba = ReadImage8(view.colour, view.matte.empty() ? 4 : 3);
  CheckSize(rgba, view, view.colour);
  if (view.matte.empty()) return AtCameraSize(std::move(rgba), view);
  if (!fs::exists(view.matte)) Fail(view.matte.string(), ": missing matte for view '", view.camera.name, "'");
  const Image8 matte = ReadImage8(view.matte, 1);
  CheckSize(matte, view, view.matte);
  Image8 straight(rgba.width, rgba.height, 4);
  for (int y = 0; y < rgba.height; ++y)
    for (int x = 0; x < rgba.width; ++x) {
      for (int c = 0; c < 3; ++c) straight.at(x, y, c) = rgba.at(x, y, c);
      straight.at(x, y, 3) = matte.at(x, y);
    }
  return AtCameraSize(std::move(straight), view);
}

std::vector<TruthView> SeenFromFarther(std::vector<TruthView> views, double distance) {
  if (!(distance >= 1)) Fail("eval: distance ", distance, ": expected 1 or more (times the cameras' distance)");
  if (distance == 1) return views;
  for (TruthView& view : views) {
    const Camera& camera = view.camera.camera;
    if (view.photo_width == 0) view.photo_width = camera.width, view.photo_height = camera.height;
    const int width = std::max(1, int(std::lround(camera.width / distance)));
    const int height = std::max(1, int(std::lround(camera.height / distance)));
    view.camera.camera = camera.Resized(width, height);
  }
  return views;
}

std::optional<std::vector<TruthView>> HeldOutTruth(const fs::path& workspace) {
  const fs::path truth = workspace / "truth";
  if (!fs::is_directory(truth)) return std::nullopt;
  std::vector<TruthView> views;
  for (const View& camera : ModelViews(truth / "sparse")) {
    const fs::path parts = Companion(truth, "parts", camera.name);
    views.push_back({camera,
                     Companion(truth, "rgba", camera.name),
                     {},
                     /*premultiplied=*/true,
                     fs::exists(parts) ? parts : fs::path()});
  }
  return views;
}

std::vector<TruthView> InputTruth(const fs::path& workspace) {
  std::vector<TruthView> views;
  for (const View& camera : ModelViews(workspace / "sparse")) {
    const fs::path foreground = Companion(workspace, "foreground", camera.name);
    if (fs::exists(foreground)) {
      views.push_back({camera, foreground, {}, true, {}});
    } else {
      views.push_back(
          {camera, workspace / "images" / camera.name, Companion(workspace, "mattes", camera.name), false, {}});
    }
  }
  return views;
}

std::optional<TruthAlignment> AlignTruthToWorkspace(const fs::path& workspace) {
  const fs::path true_inputs = workspace / "truth" / "input_sparse";
  if (!fs::is_directory(true_inputs)) return std::nullopt;
  // CompareCameras fits "estimated -> true"; here the truth's frame is the one moved.
  const CameraAccuracy fit = CompareCameras(ModelViews(true_inputs), ModelViews(workspace / "sparse"));
  TruthAlignment alignment;
  alignment.truth_to_workspace = fit.estimated_to_true;
  alignment.matched_views = fit.matched;
  alignment.mean_rotation_degrees = fit.mean_rotation_degrees;
  alignment.mean_center_error = fit.mean_center_error;
  return alignment;
}

void ApplyAlignment(const TruthAlignment& alignment, std::vector<TruthView>* views) {
  for (TruthView& view : *views) view.camera.pose = TransformPose(view.camera.pose, alignment.truth_to_workspace);
}

}  // namespace voltree
