#include "render/scene_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "render/gl.h"
#include "render/gl_context.h"
#include "render/offscreen_render.h"

namespace voltree {
namespace {

using Clock = std::chrono::steady_clock;
double Ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

void Accumulate(const FrameStats& tree, FrameStats* total) {
  total->cells += tree.cells;
  total->billboards += tree.billboards;
  total->traversal_ms += tree.traversal_ms;
  if (tree.fragments >= 0) total->fragments = std::max<int64_t>(total->fragments, 0) + tree.fragments;
  if (tree.min_level >= 0)
    total->min_level = total->min_level < 0 ? tree.min_level : std::min(total->min_level, tree.min_level);
  total->max_level = std::max(total->max_level, tree.max_level);
  if (total->cells_per_level.size() < tree.cells_per_level.size())
    total->cells_per_level.resize(tree.cells_per_level.size(), 0);
  for (size_t level = 0; level < tree.cells_per_level.size(); ++level)
    total->cells_per_level[level] += tree.cells_per_level[level];
}

}  // namespace

void SceneRenderOptions::Check() const { tree.Check(); }

std::vector<size_t> VisibleBackToFront(const std::vector<Sphere>& spheres, const View& view, bool cull) {
  const Eigen::Vector3d eye = view.pose.Center();
  std::vector<size_t> order;
  if (cull) {
    const Frustum frustum(view);
    for (size_t i = 0; i < spheres.size(); ++i)
      if (frustum.MayIntersect(spheres[i])) order.push_back(i);
  } else {
    order.resize(spheres.size());
    std::iota(order.begin(), order.end(), size_t(0));
  }
  std::vector<double> distance(spheres.size());
  for (size_t i : order) distance[i] = (spheres[i].centre - eye).norm();
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return distance[a] != distance[b] ? distance[a] > distance[b] : a < b; });
  return order;
}

DepthRange SceneDepthRange(const Eigen::Vector3d& eye, const std::vector<Sphere>& visible,
                           const std::optional<SceneGround>& ground) {
  double nearest = std::numeric_limits<double>::infinity(), farthest = 0;
  for (const Sphere& s : visible) {
    const double d = (s.centre - eye).norm();
    nearest = std::min(nearest, d - s.radius);
    farthest = std::max(farthest, d + s.radius);
  }
  if (ground) {
    const Eigen::Vector2d lo = ground->centre - 0.5 * ground->size, hi = ground->centre + 0.5 * ground->size;
    const Eigen::Vector2d closest = eye.head<2>().cwiseMax(lo).cwiseMin(hi);
    nearest = std::min(nearest, Eigen::Vector3d(closest.x(), closest.y(), 0).operator-(eye).norm());
    for (double x : {lo.x(), hi.x()})
      for (double y : {lo.y(), hi.y()}) farthest = std::max(farthest, (Eigen::Vector3d(x, y, 0) - eye).norm());
  }
  if (farthest <= 0) return {};  // nothing to draw
  farthest *= 1.01;
  // Half the nearest distance: a point at Euclidean distance d off the axis has a smaller depth
  // (d cos angle; cos >= 0.5 up to 120 degrees of diagonal field of view). The floor keeps the
  // depth precision of a 1e3 far/near ratio.
  const double near = std::max(0.5 * nearest, 1e-3 * farthest);
  return {near, std::max(farthest, 2 * near)};
}

std::vector<View> SceneOrbitCameras(const Sphere& bounds, const OrbitOptions& options) {
  return OrbitCamerasAround(bounds.centre, std::max(bounds.radius, 1e-6), 1.7 * std::max(bounds.radius, 1e-6), 25, -60,
                            options);
}

SceneRenderer::SceneRenderer(const Scene& scene, const std::vector<VtreeAsset>& assets) : scene_(scene) {
  if (assets.size() != scene.assets.size())
    Fail(scene.name, ": ", assets.size(), " assets loaded for ", scene.assets.size(), " named");
  for (size_t i = 0; i < assets.size(); ++i) {
    try {
      renderers_.push_back(std::make_unique<TreeRenderer>(assets[i]));
    } catch (const Error& error) {
      Fail(scene.name, ": assets.", scene.assets[i].name, ": ", error.what());
    }
  }
  for (const SceneInstance& instance : scene.instances) {
    if (instance.asset < 0 || size_t(instance.asset) >= assets.size())
      Fail(scene.name, ": an instance names asset ", instance.asset, " of ", assets.size());
    instance.transform.Check();
  }
  lod_states_.resize(scene.instances.size());
}

std::vector<Sphere> SceneRenderer::InstanceSpheres(double billboard_scale) const {
  std::vector<Sphere> spheres;
  spheres.reserve(scene_.instances.size());
  for (const SceneInstance& instance : scene_.instances) {
    const TreeRenderer& renderer = *renderers_[instance.asset];
    spheres.push_back({instance.transform.ToWorld(renderer.BoundingCenter()),
                       instance.transform.scale * renderer.BoundingRadius(billboard_scale)});
  }
  return spheres;
}

Sphere SceneSphere(const Scene& scene, const std::vector<Sphere>& spheres) {
  if (spheres.empty()) {
    if (!scene.ground) Fail(scene.name, ": the scene has neither instances nor a ground to look at");
    return {Eigen::Vector3d(scene.ground->centre.x(), scene.ground->centre.y(), 0), 0.5 * scene.ground->size.norm()};
  }
  Eigen::Vector3d lo = spheres[0].centre, hi = spheres[0].centre;
  for (const Sphere& s : spheres) {
    lo = lo.cwiseMin(s.centre - Eigen::Vector3d::Constant(s.radius));
    hi = hi.cwiseMax(s.centre + Eigen::Vector3d::Constant(s.radius));
  }
  Sphere bounds{0.5 * (lo + hi), 0};
  for (const Sphere& s : spheres) bounds.radius = std::max(bounds.radius, (s.centre - bounds.centre).norm() + s.radius);
  return bounds;
}

Sphere SceneRenderer::Bounds(double billboard_scale) const {
  return SceneSphere(scene_, InstanceSpheres(billboard_scale));
}

GpuMemory SceneRenderer::GpuBytes() const {
  GpuMemory total;
  for (const auto& renderer : renderers_) {
    const GpuMemory bytes = renderer->GpuBytes();
    total.buffers += bytes.buffers, total.atlas += bytes.atlas;
  }
  return total;
}

void SceneRenderer::ResetLodHistory() {
  for (auto& state : lod_states_) state.clear();
}

SceneFrameStats SceneRenderer::Draw(const View& view, const SceneRenderOptions& options) {
  options.Check();
  view.camera.Check();
  const auto start = Clock::now();
  const std::vector<Sphere> spheres = InstanceSpheres(options.tree.billboard_scale);
  const std::vector<size_t> order = VisibleBackToFront(spheres, view, options.cull);
  std::vector<Sphere> visible;
  for (size_t i : order) visible.push_back(spheres[i]);
  const DepthRange depth = SceneDepthRange(view.pose.Center(), visible, scene_.ground);
  SceneFrameStats stats;
  stats.instances_drawn = order.size();
  stats.instances_culled = spheres.size() - order.size();
  if (scene_.ground) {
    const auto& rgb = scene_.ground->colour;  // the target stores sRGB
    ground_.Draw(view, depth, *scene_.ground, Eigen::Vector3f(rgb[0], rgb[1], rgb[2]) / 255.0f);
  }
  for (size_t i : order) {
    const SceneInstance& instance = scene_.instances[i];
    TreeDraw draw;
    draw.model = instance.transform;
    draw.depth = depth;
    draw.lod_state = options.tree.lod_history ? &lod_states_[i] : nullptr;
    draw.finish = false;  // once for the frame, below
    Accumulate(renderers_[instance.asset]->Draw(view, options.tree, draw), &stats.trees);
  }
  glFinish();
  CheckGl("render: drawing the scene");
  stats.frame_ms = Ms(start, Clock::now());
  stats.trees.frame_ms = stats.frame_ms;
  return stats;
}

Image8 SceneRenderer::Render(const View& view, const SceneRenderOptions& options, SceneFrameStats* stats) {
  return RenderOffscreen(target_, view.camera, options.tree.background, [&] {
    const SceneFrameStats frame = Draw(view, options);
    if (stats) *stats = frame;
  });
}

}  // namespace voltree
