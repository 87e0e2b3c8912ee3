// The scene's ground: an opaque rectangle on z = 0 drawn with the frame's projection and depth
// range, so that the trees drawn after it depth-test against it. Shared by the asset scenes
// (render/scene_renderer.h) and the mesh scenes (lod/mesh_scene_renderer.h).
#pragma once

#include <Eigen/Core>

#include "core/camera.h"
#include "render/gl_objects.h"
#include "render/projection.h"
#include "render/scene.h"
#include "render/shader.h"

namespace voltree {

class GroundRenderer {
 public:
  GroundRenderer();  // needs a current GL context

  // Draws `ground` in `colour` (what the target stores: sRGB or linear, the caller's choice) with
  // depth test and write, no blending.
  void Draw(const View& view, const DepthRange& depth, const SceneGround& ground, const Eigen::Vector3f& colour) const;

 private:
  ShaderProgram program_;
  GlVertexArray vertex_array_;  // empty: the ground comes from gl_VertexID
};

}  // namespace voltree
