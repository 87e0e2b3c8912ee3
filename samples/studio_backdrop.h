// The studio's background: a sky with a gradient, a sun glow and soft clouds, and an endless
// ground plane at z = 0 with grass, soil and stones at many scales, so that COLMAP finds
// features to match. The realistic style adds bushes, rocks and other trees (studio_clutter.h)
// and a distant skyline of hills, tree lines and buildings. Procedural in world space (nothing
// repeats), deterministic from the seed.
#pragma once

#include <cstdint>

#include "core/camera.h"
#include "render/gl_objects.h"
#include "render/shader.h"
#include "samples/studio_clutter.h"
#include "samples/studio_lighting.h"

namespace voltree {

class StudioBackdrop {
 public:
  // `scene_size` (metres, e.g. the tree's height) scales the haze distance; `clutter` is drawn
  // when it holds objects (the realistic style), with the skyline at its wall radius around
  // `centre`. Needs a current context.
  StudioBackdrop(uint64_t seed, double scene_size, ClutterLayout clutter = {},
                 Eigen::Vector2d centre = Eigen::Vector2d::Zero());

  // Fills the bound framebuffer of size (camera size x supersample) with linear RGB, alpha 1.
  void Draw(const View& view, const StudioLighting& lighting, int supersample) const;

 private:
  ShaderProgram program_;
  GlVertexArray empty_vertex_array_;  // the full-screen triangle comes from gl_VertexID
  uint64_t seed_;
  double scene_size_;
  ClutterLayout clutter_;
  Eigen::Vector2d centre_;
};

}  // namespace voltree
