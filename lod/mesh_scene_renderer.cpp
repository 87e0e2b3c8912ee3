#include "lod/mesh_scene_renderer.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"
#include "core/srgb.h"
#include "lod/occlusion_factor.h"
#include "render/gl.h"
#include "render/gl_context.h"
#include "render/instance_view.h"
#include "render/offscreen_render.h"
#include "samples/studio_layers.h"
#include "samples/studio_options.h"

namespace voltree {
namespace {

Eigen::Vector3f Linear(const std::array<uint8_t, 3>& srgb) {
  return {SrgbToLinear(srgb[0] / 255.0f), SrgbToLinear(srgb[1] / 255.0f), SrgbToLinear(srgb[2] / 255.0f)};
}

void Add(const MeshFrameCounts& drawn, MeshFrameCounts* total) {
  total->triangles += drawn.triangles;
  total->points += drawn.points;
  total->lines += drawn.lines;
  total->ellipsoids += drawn.ellipsoids;
  total->full_instances += drawn.full_instances;
  total->reduced_instances += drawn.reduced_instances;
  total->occluded_instances += drawn.occluded_instances;
  total->visibility_tested += drawn.visibility_tested;
  total->visible_sum += drawn.visible_sum;
}

// The premultiplied linear frame as 8-bit straight alpha, over an opaque background if one is given.
Image8 Encode(const ImageF& linear, const std::array<float, 4>& background) {
  ImageF backdrop(linear.width, linear.height, 3);
  if (background[3] <= 0) return Unpremultiply(ComposeStudioLayers(linear, backdrop).foreground);
  for (size_t p = 0; p < backdrop.pixels.size(); ++p) backdrop.pixels[p] = SrgbToLinear(background[p % 3]);
  const Image8 photo = ComposeStudioLayers(linear, backdrop).photo;
  Image8 out(photo.width, photo.height, 4);
  for (size_t p = 0; p < size_t(photo.width) * photo.height; ++p) {
    for (int c = 0; c < 3; ++c) out.pixels[4 * p + c] = photo.pixels[3 * p + c];
    out.pixels[4 * p + 3] = 255;
  }
  return out;
}

}  // namespace

MeshSceneRenderer::MeshSceneRenderer(const Scene& scene, const std::vector<TreeMesh>& meshes,
                                     const MeshLodOptions& options)
    : scene_(scene), options_(options), lighting_(MakeStudioLighting(StudioOptions{})) {
  options_.Check();
  if (meshes.size() != scene.meshes.size())
    Fail(scene.name, ": ", meshes.size(), " meshes loaded for ", scene.meshes.size(), " named");
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const int mesh = scene.instances[i].mesh;
    if (mesh < 0 || size_t(mesh) >= meshes.size())
      Fail(scene.name, ": instances[", i, "] names no mesh (a mesh LOD method draws the trees in meshes)");
    scene.instances[i].transform.Check();
  }
  for (size_t m = 0; m < meshes.size(); ++m) {
    const std::string name = Str(scene.name, ": meshes.", scene.meshes[m].name);
    try {
      models_.push_back(std::make_unique<MeshLodModel>(meshes[m], name, options_));
    } catch (const Error& error) {
      Fail(name, ": ", error.what());
    }
  }
  if (FragmentCounter::Available()) counter_ = std::make_unique<FragmentCounter>();
}

std::vector<std::string> MeshSceneRenderer::Notes() const {
  std::vector<std::string> notes;
  for (const auto& model : models_) notes.insert(notes.end(), model->notes().begin(), model->notes().end());
  return notes;
}

std::vector<Sphere> MeshSceneRenderer::InstanceSpheres() const {
  std::vector<Sphere> spheres;
  for (const SceneInstance& instance : scene_.instances) {
    const MeshLodModel& model = *models_[instance.mesh];
    spheres.push_back({instance.transform.ToWorld(0.5 * (model.lo() + model.hi())),
                       instance.transform.scale * 0.5 * (model.hi() - model.lo()).norm()});
  }
  return spheres;
}

Sphere MeshSceneRenderer::Bounds() const { return SceneSphere(scene_, InstanceSpheres()); }

GpuMemory MeshSceneRenderer::GpuBytes() const {
  GpuMemory total;
  for (const auto& model : models_) {
    const GpuMemory bytes = model->GpuBytes();
    total.buffers += bytes.buffers, total.atlas += bytes.atlas;
  }
  return total;
}

// Pixels per mesh unit at the tree's box centre, in the instance's own frame (its scale included).
double MeshSceneRenderer::PixelsPerUnit(const SceneInstance& instance, const View& view) const {
  const MeshLodModel& model = *models_[instance.mesh];
  const Eigen::Vector3d eye = instance.transform.ToAsset(view.pose.Center());
  return view.camera.FocalY() / std::max((eye - 0.5 * (model.lo() + model.hi())).norm(), 1e-9);
}

std::vector<MeshLodLevel> MeshSceneRenderer::Levels(const View& view) const {
  std::vector<MeshLodLevel> levels;
  for (const SceneInstance& instance : scene_.instances)
    levels.push_back(models_[instance.mesh]->Choose(PixelsPerUnit(instance, view)));
  return levels;
}

void MeshSceneRenderer::ResetOcclusionHistory() {
  previous_depth_.reset();
  smoothed_visible_.clear();
  last_occlusion_.clear();
  last_prepass_ = false;
}

void MeshSceneRenderer::DrawFrame(const View& view, const DepthRange& depth, const std::vector<size_t>& order,
                                  const std::vector<MeshLodLevel>& levels, MeshFrameCounts* counts,
                                  int64_t* fragments) const {
  target_->Bind();
  target_->Clear(0, 0, 0, 0);
  if (scene_.ground && depth.far > depth.near) ground_.Draw(view, depth, *scene_.ground, Linear(scene_.ground->colour));
  if (fragments) counter_->Begin();
  for (size_t k = 0; k < order.size(); ++k) {
    const SceneInstance& instance = scene_.instances[order[k]];
    StudioLighting lighting = lighting_;  // the sun stays put in the world as the tree turns
    lighting.sun_direction = instance.transform.DirectionToAsset(lighting_.sun_direction.cast<double>()).cast<float>();
    const double scale = instance.transform.scale;
    Add(models_[instance.mesh]->Draw(levels[k], ViewInAssetFrame(view, instance.transform), lighting,
                                     depth.near / scale, depth.far / scale),
        counts);
  }
  if (fragments) *fragments = static_cast<int64_t>(counter_->End());
}

Image8 MeshSceneRenderer::Render(const View& view, const std::array<float, 4>& background, bool count_fragments,
                                 SceneFrameStats* stats) {
  view.camera.Check();
  const std::vector<Sphere> spheres = InstanceSpheres();
  std::vector<size_t> order = VisibleBackToFront(spheres, view);
  std::reverse(order.begin(), order.end());  // front to back
  std::vector<Sphere> visible;
  for (size_t i : order) visible.push_back(spheres[i]);
  const DepthRange depth = SceneDepthRange(view.pose.Center(), visible, scene_.ground);

  // Plan and build the models first, so that the frame time is the drawing alone.
  std::vector<double> pixels_per_unit;
  std::vector<MeshLodLevel> levels;
  for (size_t i : order) {
    const SceneInstance& instance = scene_.instances[i];
    pixels_per_unit.push_back(PixelsPerUnit(instance, view));
    levels.push_back(models_[instance.mesh]->Choose(pixels_per_unit.back()));
    models_[instance.mesh]->Prepare(levels.back());
  }

  const int s = options_.supersample;
  if (!target_ || target_->width() != view.camera.width * s || target_->height() != view.camera.height * s)
    target_ = std::make_unique<Framebuffer>(view.camera.width * s, view.camera.height * s, ColorFormat::kRGBA16F);
  SceneFrameStats frame;
  frame.mesh = MeshFrameCounts{};
  frame.instances_drawn = order.size();
  frame.instances_culled = spheres.size() - order.size();
  double ms = 0;  // the drawing, and neubert's pre-pass, depth read-backs and tests
  const auto timed = [&ms](const auto& work) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };

  const bool neubert = options_.method == MeshLodMethod::kNeubert;
  if (neubert) {
    // No previous frame of this size: a depth pre-pass of every tree at its unoccluded level.
    last_prepass_ = !previous_depth_ || previous_depth_->width() != target_->width() ||
                    previous_depth_->height() != target_->height();
    if (last_prepass_)
      timed([&] {
        MeshFrameCounts ignored;
        DrawFrame(view, depth, order, levels, &ignored);
        previous_depth_ = FrameDepth::Read(view, depth, s);
      });
    smoothed_visible_.resize(scene_.instances.size());
    last_occlusion_.assign(scene_.instances.size(), InstanceOcclusion{});
    timed([&] {
      for (size_t k = 0; k < order.size(); ++k) {
        const SceneInstance& instance = scene_.instances[order[k]];
        const MeshLodModel& model = *models_[instance.mesh];
        InstanceOcclusion& occlusion = last_occlusion_[order[k]];
        occlusion.drawn = true;
        occlusion.measured = VisibleFraction(model.crown_samples(), instance.transform, (model.hi() - model.lo()).z(),
                                             *previous_depth_, options_.occlusion);
        occlusion.smoothed =
            SmoothedVisibility(smoothed_visible_[order[k]], occlusion.measured.fraction, options_.occlusion.fall);
        smoothed_visible_[order[k]] = occlusion.smoothed;
        levels[k] = model.Choose(pixels_per_unit[k], occlusion.smoothed);
        occlusion.level = levels[k];
        frame.mesh->visibility_tested += 1;
        frame.mesh->visible_sum += occlusion.smoothed;
      }
    });
    for (size_t k = 0; k < order.size(); ++k) models_[scene_.instances[order[k]].mesh]->Prepare(levels[k]);
  }

  const bool count = count_fragments && counter_;
  timed([&] {
    DrawFrame(view, depth, order, levels, &*frame.mesh, count ? &frame.trees.fragments : nullptr);
    if (neubert) previous_depth_ = FrameDepth::Read(view, depth, s);
  });
  frame.frame_ms = ms;
  frame.trees.frame_ms = frame.frame_ms;
  CheckGl("render: drawing the scene's meshes");
  const Image8 image = Encode(downsampler_.Downsample(*target_, s), background);
  if (stats) *stats = frame;
  return image;
}

}  // namespace voltree
