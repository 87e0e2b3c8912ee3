#include "render/tree_renderer_job.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/gl_context.h"
#include "render/orbit.h"

namespace voltree {

void RenderJobOptions::Check() const {
  render.Check();
  if ((orbit > 0) == !cameras.empty()) Fail("render: give exactly one of --orbit N and --cameras MODEL_DIR");
  if (orbit < 0) Fail("render: --orbit must be >= 1, got ", orbit);
  if (width < 0 || height < 0 || (width == 0) != (height == 0)) Fail("render: bad --size ", width, "x", height);
  if (output.empty()) Fail("render: an output folder (-o DIR) is required");
}

std::array<int, 2> ParseSize(const std::string& text, const std::string& what) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1)
    Fail(what, ": expected WIDTHxHEIGHT such as 512x512, got '", text, "'");
  return {w, h};
}

std::array<float, 4> ParseBackground(const std::string& text) {
  int r = 0, g = 0, b = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d%c", &r, &g, &b, &rest) != 3 || std::min({r, g, b}) < 0 ||
      std::max({r, g, b}) > 255)
    Fail("--background: expected R,G,B with components 0..255 such as 135,180,230, got '", text, "'");
  return {r / 255.0f, g / 255.0f, b / 255.0f, 1.0f};
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

std::vector<View> JobCameras(const RenderJobOptions& options, const VtreeAsset& asset) {
  if (options.orbit > 0) {
    OrbitOptions orbit;
    orbit.frames = options.orbit;
    orbit.width = options.width > 0 ? options.width : 512;
    orbit.height = options.height > 0 ? options.height : 512;
    return OrbitCameras(asset, orbit);
  }
  std::vector<View> views = ReadColmapText(options.cameras).Views();
  if (views.empty()) Fail(options.cameras.string(), ": the model has no registered images");
  for (View& view : views) {
    if (options.width > 0) view.camera = ResizeCamera(view.camera, options.width, options.height);
    view.name = std::filesystem::path(view.name).filename().replace_extension(".png").string();
  }
  return views;
}

}  // namespace

RenderJobResult RunRenderJob(const RenderJobOptions& options, Progress* progress) {
  options.Check();
  CheckCanWrite(options.output, options.force);
  const VtreeAsset asset = ReadAsset(options.asset);
  const std::vector<View> cameras = JobCameras(options, asset);
  StagedDirectory staged(options.output, options.force);
  GlContext context;
  TreeRenderer renderer(asset);
  RenderJobResult result;
  result.renderer = context.renderer();
  nlohmann::json frames = nlohmann::json::array();
  for (size_t i = 0; i < cameras.size(); ++i) {
    FrameStats stats;
    const Image8 image = renderer.Render(cameras[i], options.render, &stats);
    WriteImage(staged.path() / cameras[i].name, image);
    result.frames.push_back(cameras[i].name);
    result.stats.push_back(stats);
    frames.push_back({{"file", cameras[i].name}, {"cells", stats.cells}, {"billboards", stats.billboards},
                      {"levels", {stats.min_level, stats.max_level}},
                      {"views", {stats.views.first, stats.views.second}},
                      {"weights", {stats.views.first_weight, stats.views.second_weight}}});
    if (progress && (i + 1) % 10 == 0) progress->Say("render", Str(i + 1, " of ", cameras.size(), " frames"));
  }
  std::vector<double> ms;
  double billboards = 0;
  for (const FrameStats& s : result.stats) ms.push_back(s.frame_ms), billboards += double(s.billboards);
  std::sort(ms.begin(), ms.end());
  result.median_ms = ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
  result.mean_billboards = billboards / double(ms.size());
  // Timings vary run to run, so they stay out of the folder: its files are deterministic.
  WriteFileAtomic(staged.path() / "frames.json", nlohmann::json{{"asset", options.asset.string()}, {"frames", frames}}.dump(2) + "\n");
  staged.Commit();
  return result;
}

}  // namespace voltree
