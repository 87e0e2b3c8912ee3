#include "render/tree_renderer_job.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/gl_context.h"
#include "render/frame_source.h"
#include "render/orbit.h"
#include "render/scene_renderer.h"
#include "render/turntable.h"

namespace voltree {

void RenderJobOptions::Check() const {
  render.Check();
  if ((orbit > 0) == !cameras.empty())
    FailOption("RenderJobOptions.orbit", "N and --cameras MODEL_DIR: give exactly one of them");
  if (orbit < 0) FailOption("RenderJobOptions.orbit", "must be >= 1, got ", orbit);
  if (width < 0 || height < 0 || (width == 0) != (height == 0))
    FailOption("RenderJobOptions.width", "must be positive in width and height, got ", width, "x", height);
  if (output.empty() && turntable.empty())
    Fail("render: an output folder (-o DIR) or --turntable FILE.mp4 is required");
  if (!turntable.empty() && orbit == 0)
    FailOption("RenderJobOptions.turntable", "encodes orbit frames; it cannot be used with --cameras");
  if (max_level < -1) FailOption("RenderJobOptions.max_level", "must be an octree level, 0 or more, got ", max_level);
  if (max_level >= 0 && IsSceneFile(asset))
    FailOption("RenderJobOptions.max_level", "applies to a .vtree asset, not to a scene (", asset.string(), ")");
  if (!asset_folder.empty() && !IsSceneFile(asset))
    FailOption("RenderJobOptions.asset_folder", "applies to a scene (.json), not to ", asset.string());
}

Camera ResizeCamera(const Camera& camera, int width, int height) {
  camera.Check();
  const double sx = double(width) / camera.width, sy = double(height) / camera.height;
  Camera out = camera;
  out.width = width;
  out.height = height;
  const bool one_focal = camera.model == CameraModel::kSimplePinhole || camera.model == CameraModel::kSimpleRadial ||
                         camera.model == CameraModel::kRadial;
  if (one_focal) {
    if (std::abs(sx - sy) > 1e-6 * std::max(sx, sy))
      Fail("render: --size ", width, "x", height, " changes the aspect ratio of a ", CameraModelName(camera.model),
           " camera (", camera.width, "x", camera.height, "), which has one focal length");
    out.params[0] *= sx, out.params[1] *= sx, out.params[2] *= sy;
  } else {
    out.params[0] *= sx, out.params[1] *= sy, out.params[2] *= sx, out.params[3] *= sy;
  }
  return out;
}

namespace {

OrbitOptions JobOrbit(const RenderJobOptions& options) {
  OrbitOptions orbit;
  orbit.frames = options.orbit;
  orbit.width = options.width > 0 ? options.width : 512;
  orbit.height = options.height > 0 ? options.height : 512;
  return orbit;
}

std::vector<View> ModelCameras(const RenderJobOptions& options) {
  std::vector<View> views = ReadColmapText(options.cameras).Views();
  if (views.empty()) Fail(options.cameras.string(), ": the model has no registered images");
  for (View& view : views) {
    if (options.width > 0) view.camera = ResizeCamera(view.camera, options.width, options.height);
    view.name = std::filesystem::path(view.name).filename().replace_extension(".png").string();
  }
  return views;
}

class AssetSource : public FrameSource {
 public:
  AssetSource(const std::filesystem::path& path, int max_level, std::vector<std::string>* notes)
      : asset_(Load(path, max_level, notes)), renderer_(asset_) {}
  std::vector<View> Orbit(const OrbitOptions& orbit) const override { return OrbitCameras(asset_, orbit); }
  Image8 Render(const View& view, const TreeRenderOptions& options, SceneFrameStats* stats) override {
    Image8 image = renderer_.Render(view, options, &stats->trees);
    stats->instances_drawn = 1, stats->instances_culled = 0, stats->frame_ms = stats->trees.frame_ms;
    return image;
  }
  GpuMemory GpuBytes() const override { return renderer_.GpuBytes(); }

 private:
  // Progressive: a truncated file draws its whole levels; --max-level loads only the coarser ones.
  static VtreeAsset Load(const std::filesystem::path& path, int max_level, std::vector<std::string>* notes) {
    VtreeLoadReport report;
    VtreeReadOptions read;
    read.allow_partial = true;
    read.max_level = max_level;
    read.report = &report;
    VtreeAsset asset = ReadAsset(path, read);
    const std::string name = path.string();
    if (report.truncated)
      notes->push_back(
          Str("warning: ", name, " is truncated; drawing levels 0..", report.levels_loaded - 1, ". ", report.missing));
    if (max_level >= 0 && uint32_t(max_level) >= report.levels_in_file)
      notes->push_back(Str("note: --max-level ", max_level, " is beyond ", name, ", whose finest level is ",
                           report.levels_in_file - 1, "; clamped to ", report.levels_in_file - 1));
    else if (max_level >= 0 && !report.truncated)
      notes->push_back(Str("note: --max-level ", max_level, ": drawing levels 0..", max_level, " of ", name, "'s 0..",
                           report.levels_in_file - 1));
    return asset;
  }

  VtreeAsset asset_;
  TreeRenderer renderer_;
};

class SceneSource : public FrameSource {
 public:
  SceneSource(const Scene& scene, double billboard_scale)
      : renderer_(scene, ReadSceneAssets(scene)), billboard_scale_(billboard_scale) {}
  std::vector<View> Orbit(const OrbitOptions& orbit) const override {
    return SceneOrbitCameras(renderer_.Bounds(billboard_scale_), orbit);
  }
  Image8 Render(const View& view, const TreeRenderOptions& options, SceneFrameStats* stats) override {
    return renderer_.Render(view, {options}, stats);
  }
  GpuMemory GpuBytes() const override { return renderer_.GpuBytes(); }

 private:
  SceneRenderer renderer_;
  double billboard_scale_;
};

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

RenderJobResult RunRenderJob(const RenderJobOptions& options, Progress* progress,
                             const MeshSceneSourceFactory& mesh_scene) {
  options.Check();
  // Refuse before slow work: existing outputs, a missing ffmpeg, a broken scene.
  if (!options.output.empty()) CheckCanWrite(options.output, options.force);
  if (!options.turntable.empty()) {
    CheckCanWrite(options.turntable, options.force);
    if (!FindOnPath("ffmpeg"))
      Fail("render: --turntable needs ffmpeg, which is not on PATH (Debian: apt-get install ffmpeg)");
  }
  std::optional<Scene> scene;
  if (mesh_scene && !IsSceneFile(options.asset))
    Fail("render: a mesh LOD method draws a scene (.json) of meshes, not ", options.asset.string());
  if (IsSceneFile(options.asset)) scene = LoadScene(options.asset, {options.asset_folder, bool(mesh_scene)});
  const std::vector<View> model_cameras = options.cameras.empty() ? std::vector<View>{} : ModelCameras(options);

  GlContext context;
  std::vector<std::string> notes;
  std::unique_ptr<FrameSource> source;
  if (scene && mesh_scene) {
    source = mesh_scene(*scene);
  } else if (scene) {
    source = std::make_unique<SceneSource>(*scene, options.render.billboard_scale);
  } else {
    source = std::make_unique<AssetSource>(options.asset, options.max_level, &notes);
  }
  const std::vector<View> cameras = options.orbit > 0 ? source->Orbit(JobOrbit(options)) : model_cameras;
  std::optional<StagedDirectory> staged;
  if (!options.output.empty()) staged.emplace(options.output, options.force);
  std::optional<VideoWriter> video;
  if (!options.turntable.empty()) {
    VideoOptions video_options;
    video_options.force = options.force;
    const auto& bg = options.render.background;
    if (bg[3] > 0) video_options.background = {bg[0], bg[1], bg[2]};
    video.emplace(options.turntable, cameras.front().camera.width, cameras.front().camera.height, video_options);
  }

  RenderJobResult result;
  result.renderer = context.renderer();
  result.notes = notes;
  for (const std::string& note : source->Notes()) result.notes.push_back(note);
  nlohmann::json frames = nlohmann::json::array();
  double drawn = 0, culled = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    SceneFrameStats frame;
    const Image8 image = source->Render(cameras[i], options.render, &frame);
    const FrameStats& stats = frame.trees;
    if (staged) WriteImage(staged->path() / cameras[i].name, image);
    if (video) video->AddFrame(image);
    result.frames.push_back(cameras[i].name);
    result.stats.push_back(stats);
    drawn += double(frame.instances_drawn), culled += double(frame.instances_culled);
    nlohmann::json record = {{"file", cameras[i].name},
                             {"cells", stats.cells},
                             {"billboards", stats.billboards},
                             {"levels", {stats.min_level, stats.max_level}}};
    if (frame.mesh) {
      result.mesh_counts.push_back(*frame.mesh);
      record["triangles"] = frame.mesh->triangles;
      record["points"] = frame.mesh->points;
      record["lines"] = frame.mesh->lines;
      record["ellipsoids"] = frame.mesh->ellipsoids;
      record["instances_full"] = frame.mesh->full_instances;
      record["instances_reduced"] = frame.mesh->reduced_instances;
      if (frame.mesh->visibility_tested > 0) {  // neubert's occlusion
        record["instances_occluded"] = frame.mesh->occluded_instances;
        record["mean_visible"] = frame.mesh->MeanVisible();
      }
    }
    if (scene) {
      record["instances_drawn"] = frame.instances_drawn;
      record["instances_culled"] = frame.instances_culled;
    } else {
      record["views"] = {stats.views.first, stats.views.second};
      record["weights"] = {stats.views.first_weight, stats.views.second_weight};
    }
    frames.push_back(record);
    if (progress && (i + 1) % 10 == 0) progress->Say("render", Str(i + 1, " of ", cameras.size(), " frames"));
  }
  std::vector<double> ms;
  double billboards = 0;
  for (const FrameStats& s : result.stats) ms.push_back(s.frame_ms), billboards += double(s.billboards);
  result.median_ms = Median(ms);
  const double n = double(std::max<size_t>(ms.size(), 1));
  result.mean_billboards = billboards / n;
  double fragments = 0;
  size_t counted = 0;
  for (const FrameStats& s : result.stats)
    if (s.fragments >= 0) fragments += double(s.fragments), ++counted;
  if (counted > 0) result.mean_fragments = fragments / double(counted);
  result.mean_instances_drawn = drawn / n;
  result.mean_instances_culled = culled / n;
  result.gpu = source->GpuBytes();
  if (video) video->Finish();
  if (staged) {
    // Timings vary run to run, so they stay out of the folder: its files are deterministic.
    WriteFileAtomic(
        staged->path() / "frames.json",
        nlohmann::json{{"asset", options.asset_label.empty() ? options.asset.string() : options.asset_label},
                       {"frames", frames}}
                .dump(2) +
            "\n");
    staged->Commit();
  }
  return result;
}

}  // namespace voltree
