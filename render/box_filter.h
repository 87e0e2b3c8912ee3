// Box-filter downsampling on the GPU: averages factor x factor texels of a supersampled target
// into one pixel, so only the small image crosses the bus. Fixed summation order: deterministic.
#pragma once

#include <memory>

#include "core/image.h"
#include "render/framebuffer.h"
#include "render/gl_objects.h"
#include "render/shader.h"

namespace voltree {

class BoxDownsampler {
 public:
  BoxDownsampler();  // needs a current context
  // RGBA float, top row first; source size must be a multiple of `factor`.
  ImageF Downsample(const Framebuffer& source, int factor);

 private:
  ShaderProgram program_;
  GlVertexArray empty_vertex_array_;
  std::unique_ptr<Framebuffer> target_;  // reused while the size stays the same
};

}  // namespace voltree
