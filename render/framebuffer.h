// An off-screen render target: one colour texture (RGBA8 or floating point) and an optional depth
// buffer, read back top row first like every Image in voltree.
#pragma once

#include "core/image.h"
#include "render/gl.h"
#include "render/gl_objects.h"

namespace voltree {

enum class ColorFormat { kRGBA8, kRGBA16F, kRGBA32F };

class Framebuffer {
 public:
  // Needs a current GL context. Throws Error when the driver rejects the size or format.
  Framebuffer(int width, int height, ColorFormat format, bool with_depth = true);
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  ColorFormat format() const { return format_; }
  GLuint color_texture() const { return color_.id(); }

  // Binds for drawing and sets the viewport to the whole target.
  void Bind() const;
  void Clear(float r, float g, float b, float a, float depth = 1.0f) const;

  // RGBA, top row first. The 8-bit read clamps and rounds floating point targets.
  Image8 ReadImage8() const;
  ImageF ReadImageF() const;

 private:
  int width_, height_;
  ColorFormat format_;
  // Declared so that the framebuffer is deleted before what is attached to it.
  GlTextureName color_;
  GlRenderbufferName depth_;  // none without depth
  GlFramebufferName framebuffer_;
};

}  // namespace voltree
