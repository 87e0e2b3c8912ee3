#include "lod/lod_view_renderer.h"

#include <chrono>
#include <cstring>
#include <string>

#include "samples/depth_range.h"
#include "render/gl.h"
#include "samples/studio_layers.h"

namespace voltree {
namespace {

bool HasExtension(const char* name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (extension && std::strcmp(extension, name) == 0) return true;
  }
  return false;
}

}  // namespace

LodViewRenderer::LodViewRenderer(const StudioOptions& studio, const Eigen::Vector3d& bounds_min,
                                 const Eigen::Vector3d& bounds_max)
    : lighting_((studio.Check(), MakeStudioLighting(studio))), bounds_min_(bounds_min), bounds_max_(bounds_max) {
  counts_fragments_ = HasExtension("GL_ARB_pipeline_statistics_query");
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
  GLuint query = 0;
  if (counts_fragments_) {
    glGenQueries(1, &query);
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query);
  }
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  draw(view, lighting_, near, far);
  glFinish();
  frame.draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (counts_fragments_) {
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    GLuint64 fragments = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &fragments);
    glDeleteQueries(1, &query);
    frame.fragments = static_cast<int64_t>(fragments);
  }
  CheckGl("drawing a level of detail");

  const ImageF linear = downsampler_.Downsample(*target_, supersample);
  const ImageF black(linear.width, linear.height, 3);  // ComposeStudioLayers needs a backdrop
  frame.foreground = ComposeStudioLayers(linear, black).foreground;
  return frame;
}

}  // namespace voltree
