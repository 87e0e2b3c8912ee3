// Photographs one view of a tree in the studio: the tree alone and the backdrop alone, each
// rendered supersampled and box-filtered, then composed into photo, foreground and matte.
#pragma once

#include <memory>

#include "core/camera.h"
#include "render/box_filter.h"
#include "render/framebuffer.h"
#include "render/gl_context.h"
#include "samples/studio_backdrop.h"
#include "samples/studio_layers.h"
#include "samples/studio_lighting.h"
#include "samples/studio_options.h"
#include "samples/studio_tree_renderer.h"
#include "samples/tree_mesh.h"

namespace voltree {

class StudioRenderer {
 public:
  // Creates its own headless GL context and uploads the mesh once.
  StudioRenderer(const TreeMesh& mesh, const StudioOptions& options);

  StudioLayers Photograph(const View& view);
  // The two linear renders behind Photograph: premultiplied RGBA of the tree, opaque backdrop.
  ImageF RenderTree(const View& view);
  ImageF RenderBackdrop(const View& view);
  // Coverage of the visible surface by part: R bark, G leaves (box-filtered like the tree).
  ImageF RenderParts(const View& view);

  const GlContext& context() const { return context_; }

 private:
  // A supersampled target for `view`, reused while the size stays the same.
  static const Framebuffer& Target(const View& view, int supersample, std::unique_ptr<Framebuffer>& target);

  GlContext context_;  // declared first: destroyed after every GL object below
  StudioOptions options_;
  StudioLighting lighting_;
  Eigen::Vector3d bounds_min_, bounds_max_;
  StudioTreeRenderer tree_;
  StudioBackdrop backdrop_;
  BoxDownsampler downsampler_;
  std::unique_ptr<Framebuffer> tree_target_, backdrop_target_;
};

}  // namespace voltree
