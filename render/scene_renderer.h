// Draws a Scene: a ground plane and many instances of a few .vtree assets.
//
// Each asset's TreeRenderer (its GPU buffers and atlas) is built once and shared by all of its
// instances. Per frame: each instance's bounding sphere (the asset's, moved by the instance's
// similarity) is culled against the view frustum; the visible instances are sorted back to front
// by the distance from the eye to their sphere centre, so that the premultiplied "over" of one
// tree onto the next is in order; the ground is drawn first, opaque with depth write; then each
// visible instance is ONE draw call (TreeRenderer::Draw with its transform), depth-tested against
// the ground with one depth range shared by the whole frame. LOD is per instance, evaluated in
// the instance's frame, with per-instance hysteresis state.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/frustum.h"
#include "render/ground_renderer.h"
#include "render/gl_objects.h"
#include "render/orbit.h"
#include "render/projection.h"
#include "render/scene.h"
#include "render/shader.h"
#include "render/tree_renderer.h"

namespace voltree {

struct SceneRenderOptions {
  TreeRenderOptions tree;  // LOD, background, billboard scale, level tint: the same for every instance
  bool cull = true;        // frustum culling (off only to measure what it saves)
  void Check() const;
};

// Scenes of meshes drawn by a mesh LOD method (lod/mesh_scene_renderer.h): what a frame drew.
struct MeshFrameCounts {
  size_t triangles = 0;  // of the meshes drawn, the ellipsoids' surfaces and the lines' quads
  size_t points = 0, lines = 0, ellipsoids = 0;
  size_t full_instances = 0;      // drawn as the full mesh (near, or the method could not be built)
  size_t reduced_instances = 0;   // drawn by the method at a reduced level
  size_t occluded_instances = 0;  // neubert: drawn with fewer leaves because trees in front hide them
  size_t visibility_tested = 0;   // neubert: instances whose crown was tested against a depth buffer
  double visible_sum = 0;         // neubert: their smoothed visible fractions f, summed
  size_t Primitives() const { return triangles + points + lines + ellipsoids; }
  double MeanVisible() const { return visibility_tested ? visible_sum / double(visibility_tested) : 1.0; }
};

struct SceneFrameStats {
  FrameStats trees;  // summed over the drawn instances (cells, billboards, traversal ms); level range over all
  std::optional<MeshFrameCounts> mesh;  // scenes of meshes only
  size_t instances_drawn = 0, instances_culled = 0;
  double frame_ms = 0;  // culling, sorting, ground, every tree and glFinish (no read-back)
};

// The instances to draw, back to front: those whose sphere may intersect the view's frustum (all
// when !cull), by decreasing distance from the eye to the sphere centre, ties by index.
std::vector<size_t> VisibleBackToFront(const std::vector<Sphere>& spheres, const View& view, bool cull = true);

// One depth range for a frame that holds the visible spheres and the ground rectangle (z = 0).
DepthRange SceneDepthRange(const Eigen::Vector3d& eye, const std::vector<Sphere>& visible,
                           const std::optional<SceneGround>& ground);

// A sphere around `spheres` (the instances'), or the ground's extent when there are none.
Sphere SceneSphere(const Scene& scene, const std::vector<Sphere>& spheres);

// The scene orbit of `voltree render SCENE --orbit N`: 25 degrees above the horizon at 1.7 times
// the radius of `bounds` (the instances' sphere), looking at its centre, the sphere in view.
std::vector<View> SceneOrbitCameras(const Sphere& bounds, const OrbitOptions& options);

class SceneRenderer {
 public:
  // `assets` in Scene::assets order (ReadSceneAssets). Needs a current GL context.
  SceneRenderer(const Scene& scene, const std::vector<VtreeAsset>& assets);
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  const Scene& scene() const { return scene_; }
  // World bounding spheres of the instances, in Scene::instances order.
  std::vector<Sphere> InstanceSpheres(double billboard_scale) const;
  // A sphere around all instances (the ground's extent when there are none), for orbits.
  Sphere Bounds(double billboard_scale) const;
  // Buffers and atlases of all assets (shared by their instances), summed.
  GpuMemory GpuBytes() const;
  void ResetLodHistory();

  // Draws into the bound framebuffer; the caller clears colour and depth.
  SceneFrameStats Draw(const View& view, const SceneRenderOptions& options);
  // Renders into an internal framebuffer of the camera's size; straight-alpha RGBA8.
  Image8 Render(const View& view, const SceneRenderOptions& options, SceneFrameStats* stats = nullptr);

 private:
  Scene scene_;
  std::vector<std::unique_ptr<TreeRenderer>> renderers_;  // per asset
  std::vector<std::vector<uint8_t>> lod_states_;          // per instance
  GroundRenderer ground_;
  std::unique_ptr<Framebuffer> target_;
};

}  // namespace voltree
