#include "pipeline/evaluation_truth.h"

#include "capture/calibrate_accuracy.h"
#include "core/colmap_model.h"
#include "core/error.h"

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
  if (image.width != view.camera.camera.width || image.height != view.camera.camera.height)
    Fail(file.string(), ": is ", image.width, "x", image.height, ", expected the camera's ", view.camera.camera.width,
         "x", view.camera.camera.height, " (view '", view.camera.name, "')");
}

}  // namespace

Image8 LoadTruthImage(const TruthView& view) {
  if (!fs::exists(view.colour)) Fail(view.colour.string(), ": missing truth image for view '", view.camera.name, "'");
  Image8 rgba = ReadImage8(view.colour, view.matte.empty() ? 4 : 3);
  CheckSize(rgba, view, view.colour);
  if (view.matte.empty()) return rgba;
  if (!fs::exists(view.matte)) Fail(view.matte.string(), ": missing matte for view '", view.camera.name, "'");
  const Image8 matte = ReadImage8(view.matte, 1);
  CheckSize(matte, view, view.matte);
  Image8 straight(rgba.width, rgba.height, 4);
  for (int y = 0; y < rgba.height; ++y)
    for (int x = 0; x < rgba.width; ++x) {
      for (int c = 0; c < 3; ++c) straight.at(x, y, c) = rgba.at(x, y, c);
      straight.at(x, y, 3) = matte.at(x, y);
    }
  return straight;
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
