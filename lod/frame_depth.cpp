#include "lod/frame_depth.h"

#include <cmath>

#include "core/error.h"
#include "render/gl.h"
#include "render/gl_context.h"

namespace voltree {

FrameDepth::FrameDepth(const View& view, int width, int height, std::vector<float> distances)
    : view_(view), width_(width), height_(height), distances_(std::move(distances)) {
  if (width < 1 || height < 1 || distances_.size() != size_t(width) * size_t(height))
    Fail("lod: a depth frame of ", width, "x", height, " with ", distances_.size(), " values");
}

FrameDepth FrameDepth::Read(const View& view, const DepthRange& range, int supersample) {
  range.Check();
  if (supersample < 1) Fail("lod: supersample ", supersample, " is not >= 1");
  const int width = view.camera.width * supersample, height = view.camera.height * supersample;
  std::vector<float> window(size_t(width) * size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, window.data());
  CheckGl("reading back the depth buffer");
  // Window depth back to the distance along the view axis (render/projection.h's mapping).
  const double n = range.near, f = range.far;
  std::vector<float> distances(window.size());
  for (int y = 0; y < height; ++y) {
    const float* row = window.data() + size_t(height - 1 - y) * width;  // GL rows start at the bottom
    for (int x = 0; x < width; ++x) {
      const double ndc = 2.0 * row[x] - 1;
      distances[size_t(y) * width + x] = static_cast<float>(2 * f * n / ((f + n) - ndc * (f - n)));
    }
  }
  View scaled = view;
  scaled.camera = view.camera.Resized(width, height);
  return FrameDepth(scaled, width, height, std::move(distances));
}

bool FrameDepth::Visible(const Eigen::Vector3d& world, double bias) const {
  Eigen::Vector2d pixel;
  if (!view_.WorldToPixel(world, &pixel)) return true;
  if (!(pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() < width_ && pixel.y() < height_)) return true;
  const double along = view_.pose.ToCamera(world).z();
  const auto x = static_cast<int>(pixel.x()), y = static_cast<int>(pixel.y());
  return along <= double(distances_[size_t(y) * width_ + x]) + bias;
}

}  // namespace voltree
