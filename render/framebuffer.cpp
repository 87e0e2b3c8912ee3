#include "render/framebuffer.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "render/gl_context.h"

namespace voltree {
namespace {

GLenum InternalFormat(ColorFormat format) {
  switch (format) {
    case ColorFormat::kRGBA8:
      return GL_RGBA8;
    case ColorFormat::kRGBA16F:
      return GL_RGBA16F;
    case ColorFormat::kRGBA32F:
      return GL_RGBA32F;
  }
  return GL_RGBA8;
}

// glReadPixels returns the bottom row first; voltree images start at the top.
template <typename T>
void FlipRows(Image<T>& image) {
  const size_t row = size_t(image.width) * image.channels;
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.pixels.begin() + y * row, image.pixels.begin() + (y + 1) * row,
                     image.pixels.begin() + (image.height - 1 - y) * row);
}

// RGBA rows of the colour attachment, top row first (GL reads bottom-up).
template <typename T>
Image<T> ReadBack(GLuint framebuffer, int width, int height, GLenum type) {
  Image<T> image(width, height, 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, sizeof(T) == 1 ? 1 : 4);
  glReadPixels(0, 0, width, height, GL_RGBA, type, image.pixels.data());
  CheckGl("reading back a framebuffer");
  FlipRows(image);
  return image;
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, ColorFormat format, bool with_depth)
    : width_(width), height_(height), format_(format) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width <= 0 || height <= 0 || width > max_size || height > max_size)
    Fail("framebuffer size ", width, "x", height, " is outside 1..", max_size, " (the driver's limit)");
  color_ = GlTextureName::Create();
  glTextureStorage2D(color_.id(), 1, InternalFormat(format), width, height);
  glTextureParameteri(color_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(color_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  framebuffer_ = GlFramebufferName::Create();
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  if (with_depth) {
    depth_ = GlRenderbufferName::Create();
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  }
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    Fail("OpenGL: framebuffer ", width, "x", height, " is incomplete (status 0x", std::hex, status, ")");
  CheckGl("creating a framebuffer");
}

void Framebuffer::Bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void Framebuffer::Clear(float r, float g, float b, float a, float depth) const {
  const float color[4] = {r, g, b, a};
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, color);
  if (depth_.id() != 0) glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &depth);
}

Image8 Framebuffer::ReadImage8() const {
  return ReadBack<uint8_t>(framebuffer_.id(), width_, height_, GL_UNSIGNED_BYTE);
}

ImageF Framebuffer::ReadImageF() const { return ReadBack<float>(framebuffer_.id(), width_, height_, GL_FLOAT); }

}  // namespace voltree
