// The depth buffer of a drawn frame kept with the view and depth range it was drawn with, so that
// a later frame can ask whether a world point was visible in it (Neubert et al. 2011, sec. 4:
// "the depth buffer and transformation of the previous frame").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "render/projection.h"

namespace voltree {

class FrameDepth {
 public:
  // Reads the depth attachment of the framebuffer bound for reading (glReadPixels of
  // GL_DEPTH_COMPONENT), `supersample` times the camera's size per axis, drawn with `view` and
  // `range`; stores distances along the view axis. Needs a current GL context.
  static FrameDepth Read(const View& view, const DepthRange& range, int supersample);

  // From distances along the view axis, row-major, top row first (tests; Read builds the same).
  FrameDepth(const View& view, int width, int height, std::vector<float> distances);

  const View& view() const { return view_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // Whether `world` was in front of what the frame drew at its pixel, with `bias` (world units
  // along the view axis) in its favour. Points behind the camera or projected outside the
  // viewport count as visible: the frame knows nothing about them (the paper's conservative rule).
  bool Visible(const Eigen::Vector3d& world, double bias) const;

 private:
  View view_;
  int width_ = 0, height_ = 0;
  std::vector<float> distances_;  // per pixel of width_ x height_, top row first
};

}  // namespace voltree
