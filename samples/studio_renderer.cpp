#include "samples/studio_renderer.h"

#include <algorithm>

#include "core/error.h"
#include "samples/depth_range.h"
#include "samples/studio_rig.h"

namespace voltree {
namespace {

// The realistic backdrop's clutter, kept outside the camera ring; none for the plain one.
ClutterLayout StudioClutter(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const StudioOptions& options) {
  if (options.backdrop == BackdropStyle::kPlain) return {};
  const StudioRig rig = MakeStudioRig(lo, hi, options);
  return MakeStudioClutter(options.seed, rig.target.head<2>(), hi.z() - lo.z(), 1.15 * rig.distance);
}

}  // namespace

StudioRenderer::StudioRenderer(const TreeMesh& mesh, const StudioOptions& options)
    : options_((options.Check(), options)),
      lighting_(MakeStudioLighting(options)),
      bounds_min_(mesh.Bounds().first.cast<double>()),
      bounds_max_(mesh.Bounds().second.cast<double>()),
      tree_(mesh),
      backdrop_(options.seed, (bounds_max_ - bounds_min_).maxCoeff(), StudioClutter(bounds_min_, bounds_max_, options),
                MakeStudioRig(bounds_min_, bounds_max_, options).target.head<2>()) {}

const Framebuffer& StudioRenderer::Target(const View& view, int supersample, std::unique_ptr<Framebuffer>& target) {
  const int width = view.camera.width * supersample, height = view.camera.height * supersample;
  if (!target || target->width() != width || target->height() != height)
    target = std::make_unique<Framebuffer>(width, height, ColorFormat::kRGBA16F, true);
  return *target;
}

ImageF StudioRenderer::RenderTree(const View& view) {
  const Framebuffer& target = Target(view, options_.supersample, tree_target_);
  target.Bind();
  target.Clear(0, 0, 0, 0);
  const auto [near, far] = BoxDepthRange(view, bounds_min_, bounds_max_);
  tree_.Draw(view, lighting_, near, far);
  return downsampler_.Downsample(target, options_.supersample);
}

ImageF StudioRenderer::RenderParts(const View& view) {
  const Framebuffer& target = Target(view, options_.supersample, tree_target_);
  target.Bind();
  target.Clear(0, 0, 0, 0);
  const auto [near, far] = BoxDepthRange(view, bounds_min_, bounds_max_);
  tree_.Draw(view, lighting_, near, far, /*parts=*/true);
  return downsampler_.Downsample(target, options_.supersample);
}

ImageF StudioRenderer::RenderBackdrop(const View& view) {
  const int supersample = std::min(options_.backdrop_supersample, options_.supersample);
  const Framebuffer& target = Target(view, supersample, backdrop_target_);
  target.Bind();
  backdrop_.Draw(view, lighting_, supersample);
  return downsampler_.Downsample(target, supersample);
}

StudioLayers StudioRenderer::Photograph(const View& view) {
  const ImageF tree = RenderTree(view);
  const ImageF backdrop = RenderBackdrop(view);
  return ComposeStudioLayers(tree, backdrop);
}

}  // namespace voltree
