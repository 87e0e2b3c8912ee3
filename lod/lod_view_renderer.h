// Draws a tree mesh the way the photo studio does (its shader, light and supersampling, no
// backdrop) and measures what the draw cost: wall time of the draw call with the GPU finished
// before and after, and the fragments shaded when the driver has pipeline statistics queries.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "core/camera.h"
#include "core/image.h"
#include "render/box_filter.h"
#include "render/fragment_counter.h"
#include "render/framebuffer.h"
#include "render/gl_context.h"
#include "samples/studio_lighting.h"
#include "samples/studio_options.h"
#include "samples/studio_tree_renderer.h"

namespace voltree {

struct LodFrame {
  Image8 foreground;       // RGBA, sRGB colour premultiplied by coverage, as the studio's foreground/
  double draw_ms = 0;      // both passes of the tree's draw, at the supersampled resolution
  int64_t fragments = -1;  // fragment shader invocations of both passes; -1: not available
};

class LodViewRenderer {
 public:
  // Creates its own headless GL context. `bounds_*`: a box holding every mesh it will draw (for
  // the depth range).
  LodViewRenderer(const StudioOptions& studio, const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max);

  // `tree` must have been made while this renderer's context was current (after its construction).
  // `supersample`: samples per pixel and axis, box-filtered.
  LodFrame Render(const StudioTreeRenderer& tree, const View& view, int supersample);

  // Any drawing with the same target, light, depth range and measurement: `draw` is called once
  // with the target bound and cleared (points and lines, ellipsoids).
  using DrawCall = std::function<void(const View& view, const StudioLighting& lighting, double near, double far)>;
  LodFrame Render(const DrawCall& draw, const View& view, int supersample);

  bool counts_fragments() const { return fragment_counter_.has_value(); }
  const GlContext& context() const { return context_; }

 private:
  GlContext context_;  // declared first: destroyed after every GL object below
  StudioLighting lighting_;
  Eigen::Vector3d bounds_min_, bounds_max_;
  BoxDownsampler downsampler_;
  std::unique_ptr<Framebuffer> target_;
  std::optional<FragmentCounter> fragment_counter_;  // where the driver can count fragments
};

}  // namespace voltree
