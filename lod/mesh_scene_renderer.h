// Draws a Scene whose instances are tree meshes (Scene::meshes), each with the mesh LOD method
// of MeshLodOptions at the level its screen size picks (lod/mesh_lod_model.h), switching
// between the full mesh and the method by distance. Per frame: instances whose bounding sphere
// misses the view frustum are culled; the rest are drawn front to back (opaque, depth-tested,
// so near trees hide far fragments early) after the ground, each with the studio's shader and
// light in its own frame (render/instance_view.h), into a linear supersampled target that is
// box-filtered and encoded to sRGB. Each tree's models are shared by its instances.
//
// neubert also keeps the frame's depth buffer: the next frame tests each tree's crown samples
// against it (lod/occlusion_factor.h) and lowers the level of the trees it hid. A first frame
// (or one of another size) has no previous frame: it draws a depth pre-pass of every tree at its
// unoccluded level first and tests against that, so a single still frame is pruned as well.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "lod/frame_depth.h"
#include "lod/mesh_lod_model.h"
#include "lod/mesh_lod_options.h"
#include "render/box_filter.h"
#include "render/fragment_counter.h"
#include "render/framebuffer.h"
#include "render/frustum.h"
#include "render/ground_renderer.h"
#include "render/scene.h"
#include "render/scene_renderer.h"
#include "samples/studio_lighting.h"
#include "samples/tree_mesh.h"

namespace voltree {

// What neubert's occlusion test gave an instance in the last frame.
struct InstanceOcclusion {
  bool drawn = false;   // in view (the rest were not tested)
  Visibility measured;  // against the previous frame's (or the pre-pass's) depth
  double smoothed = 1;  // f after the hysteresis, what lambda used
  MeshLodLevel level;   // what it drew
};

class MeshSceneRenderer {
 public:
  // `meshes` in Scene::meshes order; every instance must name a mesh. Needs a current GL context.
  MeshSceneRenderer(const Scene& scene, const std::vector<TreeMesh>& meshes, const MeshLodOptions& options);

  // What a method could not build, per mesh (see MeshLodModel).
  std::vector<std::string> Notes() const;
  std::vector<Sphere> InstanceSpheres() const;
  Sphere Bounds() const;
  GpuMemory GpuBytes() const;
  // The level each instance would draw from `view` (culled ones included), in instance order.
  std::vector<MeshLodLevel> Levels(const View& view) const;

  // Straight-alpha RGBA8 of the camera's size; over `background` (straight RGBA in [0, 1]) when
  // its alpha is > 0. `count_fragments`: the trees' fragment shader invocations into stats
  // (-1 where the driver cannot count them).
  Image8 Render(const View& view, const std::array<float, 4>& background, bool count_fragments,
                SceneFrameStats* stats = nullptr);

  // neubert: the last frame's test per instance, in instance order (empty for other methods),
  // and whether that frame drew a depth pre-pass for want of a previous frame.
  const std::vector<InstanceOcclusion>& LastOcclusion() const { return last_occlusion_; }
  bool LastFrameHadPrepass() const { return last_prepass_; }
  // Forgets the previous frame and the smoothed f: the next frame is a first frame.
  void ResetOcclusionHistory();

 private:
  double PixelsPerUnit(const SceneInstance& instance, const View& view) const;
  // Clears the target and draws the ground and the instances `order` at `levels`; with
  // `fragments`, the trees' fragment shader invocations (the ground's not counted).
  void DrawFrame(const View& view, const DepthRange& depth, const std::vector<size_t>& order,
                 const std::vector<MeshLodLevel>& levels, MeshFrameCounts* counts, int64_t* fragments = nullptr) const;

  Scene scene_;
  MeshLodOptions options_;
  std::vector<std::unique_ptr<MeshLodModel>> models_;  // per scene mesh
  StudioLighting lighting_;
  GroundRenderer ground_;
  BoxDownsampler downsampler_;
  std::unique_ptr<Framebuffer> target_;
  std::unique_ptr<FragmentCounter> counter_;
  // neubert's history
  std::optional<FrameDepth> previous_depth_;
  std::vector<std::optional<double>> smoothed_visible_;  // per instance
  std::vector<InstanceOcclusion> last_occlusion_;
  bool last_prepass_ = false;
};

}  // namespace voltree
