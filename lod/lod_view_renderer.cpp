#include "lod/lod_view_renderer.h"

#include <chrono>
#include <string>

#include "samples/depth_range.h"
#include "render/gl.h"
#include "samples/studio_layers.h"

namespace voltree {

LodViewRenderer::LodViewRenderer(const StudioOptions& studio, const Eigen::Vector3d& bounds_min,
                                 const Eigen::Vector3d& bounds_max)
    : lighting_((studio.Check(), MakeStudioLighting(studio))), bounds_min_(bounds_min), bounds_max_(bounds_max) {
  if (FragmentCounter::Available()) fragment_counter_.emplace();
}

LodFrame LodViewRenderer::Render(const StudioTreeRenderer& tree, const View& view, int supersample) {
  return Render([&tree](const View& at, const StudioLighting& lighting, double near,
                        double far) { tree.Draw(at, lighting, near, far); },
                view, supersample);
}

LodFrame LodViewRenderer::Render(const DrawCall& draw, const View& view, int supersample) {
  const int width = view.camera.width * supersample, height = view.camera.height * supersample;
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<Framebuffer>(width, height, ColorFormat::kRGBA16F, true);
  target_->Bind();
  target_->Clear(0, 0, 0, 0);
  const auto [near, far] = BoxDepthRange(view, bounds_min_, bounds_max_);

  LodFrame frame;
  if (fragment_counter_) fragment_counter_->Begin();
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  draw(view, lighting_, near, far);
  glFinish();
  frame.draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (fragment_counter_) frame.fragments = static_cast<int64_t>(fragment_counter_->End());
  CheckGl("drawing a level of detail");

  const ImageF linear = downsampler_.Downsample(*target_, supersample);
  const ImageF black(linear.width, linear.height, 3);  // ComposeStudioLayers needs a backdrop
  frame.foreground = ComposeStudioLayers(linear, black).foreground;
  return frame;
}

}  // namespace voltree
