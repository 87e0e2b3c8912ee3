// What `voltree render` draws, behind one interface: one .vtree asset, a scene of assets, or a
// scene of meshes (lod/mesh_scene_job.h, which the render library cannot depend on).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "render/orbit.h"
#include "render/scene.h"
#include "render/scene_renderer.h"
#include "render/tree_renderer.h"

namespace voltree {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual std::vector<View> Orbit(const OrbitOptions& orbit) const = 0;
  // Straight-alpha RGBA8 of the camera's size; `stats` filled for the frame.
  virtual Image8 Render(const View& view, const TreeRenderOptions& options, SceneFrameStats* stats) = 0;
  virtual GpuMemory GpuBytes() const = 0;
  // What the frames lack and why (e.g. a method a mesh could not build).
  virtual std::vector<std::string> Notes() const { return {}; }
};

// Makes the source of a scene whose meshes are drawn (with a GL context current).
using MeshSceneSourceFactory = std::function<std::unique_ptr<FrameSource>(const Scene& scene)>;

}  // namespace voltree
