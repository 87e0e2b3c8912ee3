#include "samples/studio.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "samples/studio_renderer.h"
#include "samples/studio_rig.h"

namespace voltree {
namespace fs = std::filesystem;
namespace {

ColmapModel TrueModel(const std::vector<View>& views) {
  ColmapModel model;
  if (views.empty()) return model;
  model.cameras[1] = views.front().camera;  // the studio's views share one camera
  for (size_t i = 0; i < views.size(); ++i) {
    ColmapImage image;
    image.image_id = static_cast<int>(i) + 1;
    image.camera_id = 1;
    image.name = views[i].name;
    image.pose = views[i].pose;
    model.images[image.image_id] = image;
  }
  return model;
}

nlohmann::json Vector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

size_t LeafTriangles(const TreeMesh& mesh) {
  size_t count = 0;
  for (const MeshGroup& group : mesh.groups)
    if (mesh.materials[group.material].alpha_mode != AlphaMode::kOpaque) count += group.indices.size() / 3;
  return count;
}

struct Folders {
  fs::path photos, mattes, foreground;
};

// Coverage of bark (R) and leaves (G) as 8-bit RGB.
Image8 PartsMask(const ImageF& coverage) {
  Image8 out(coverage.width, coverage.height, 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 2; ++c)
        out.at(x, y, c) = uint8_t(std::lround(255 * std::clamp(coverage.at(x, y, c), 0.0f, 1.0f)));
  return out;
}

}  // namespace

void PhotographTree(const TreeMesh& mesh, const StudioOptions& options, const fs::path& workspace, Progress& progress,
                    bool force) {
  options.Check();
  mesh.Check();
  const auto [lo_f, hi_f] = mesh.Bounds();
  const Eigen::Vector3d lo = lo_f.cast<double>(), hi = hi_f.cast<double>();
  const StudioRig rig = MakeStudioRig(lo, hi, options);

  StagedDirectory stage(workspace, force);
  const fs::path root = stage.path();
  const Folders inputs{root / "images", root / "mattes", root / "foreground"};
  const Folders truth{root / "truth" / "images", root / "truth" / "mattes", root / "truth" / "rgba"};
  for (const Folders& folders : {inputs, truth})
    for (const fs::path& folder : {folders.photos, folders.mattes, folders.foreground}) fs::create_directories(folder);
  const fs::path parts_folder = root / "truth" / "parts";
  fs::create_directories(parts_folder);

  StudioRenderer renderer(mesh, options);
  progress.Say("synth", Str(renderer.context().Describe(), "; ", mesh.TriangleCount(), " triangles, ",
                            rig.inputs.size(), " views + ", rig.held_out.size(), " held out at ", options.width, "x",
                            options.height, " x", options.supersample, " supersampling"));

  // PNG encoding of one view overlaps the rendering of the next; each file is independent.
  tbb::task_group writers;
  const size_t total = rig.inputs.size() + rig.held_out.size();
  size_t done = 0;
  for (const auto& [views, folders] : {std::pair{&rig.inputs, inputs}, std::pair{&rig.held_out, truth}}) {
    for (const View& view : *views) {
      const double start = progress.ElapsedSeconds();
      auto layers = std::make_shared<StudioLayers>(renderer.Photograph(view));
      // Held-out views also get masks of the visible bark and leaves, to measure thin parts apart.
      auto parts =
          std::make_shared<const Image8>(views == &rig.held_out ? PartsMask(renderer.RenderParts(view)) : Image8());
      writers.wait();
      writers.run([layers, parts, folders, parts_folder, name = view.name] {
        WriteImage(folders.photos / name, layers->photo);
        WriteImage(folders.mattes / name, layers->matte);
        WriteImage(folders.foreground / name, layers->foreground);
        if (!parts->empty()) WriteImage(parts_folder / name, *parts);
      });
      ++done;
      progress.Say("synth", Str(view.name, " ", done, "/", total, ": rendered in ",
                                static_cast<int>(1000 * (progress.ElapsedSeconds() - start)), " ms"));
    }
  }
  writers.wait();

  WriteColmapText(root / "sparse", TrueModel(rig.inputs));
  WriteColmapText(root / "truth" / "sparse", TrueModel(rig.held_out));

  const nlohmann::json bounds_min = Vector(lo), bounds_max = Vector(hi);
  nlohmann::json meta = {
      {"tree", options.tree_name},
      {"seed", options.seed},
      {"backdrop", BackdropStyleName(options.backdrop)},
      {"views", options.views},
      {"held_out", options.held_out},
      {"rings", options.rings},
      {"size", {options.width, options.height}},
      {"supersample", options.supersample},
      {"camera_model", std::string(CameraModelName(options.camera_model))},
      {"camera_params", rig.inputs.front().camera.params},
      {"fov_degrees", options.fov_degrees},
      {"camera_distance", rig.distance},
      {"camera_target", Vector(rig.target)},
      {"sun_direction", Vector(MakeStudioLighting(options).sun_direction.cast<double>())},
      {"bounds_min", bounds_min},
      {"bounds_max", bounds_max},
      {"triangles", mesh.TriangleCount()},
      {"leaf_triangles", LeafTriangles(mesh)},
      {"input_names", "images/view_NNN.png"},
      {"held_out_names", "truth/images/held_NNN.png"},
      {"parts", "truth/parts/NAME.png: coverage of the visible bark (red) and leaves (green), held-out views"},
      {"colour", "sRGB; foreground and truth/rgba premultiplied; photo = foreground over background"},
  };
  WriteFileAtomic(root / "truth" / "meta.json", meta.dump(2) + "\n");
  const nlohmann::json scene = {{"frame", "tree"},          {"up", {0, 0, 1}},          {"units", "metres"},
                                {"bounds_min", bounds_min}, {"bounds_max", bounds_max}, {"source", "studio"}};
  WriteFileAtomic(root / "scene.json", scene.dump(2) + "\n");
  stage.Commit();
  progress.Say("synth", Str("wrote ", workspace.string(), ": ", total, " views"));
}

}  // namespace voltree
