// Owners for OpenGL object names (buffers, vertex arrays, textures): deleted once, movable.
#pragma once

#include <utility>

#include "core/image.h"
#include "render/gl.h"

namespace voltree {

class GlBuffer {
 public:
  GlBuffer() = default;
  // Immutable storage filled with `bytes` bytes from `data`.
  GlBuffer(const void* data, size_t bytes);
  ~GlBuffer() { if (id_ != 0) glDeleteBuffers(1, &id_); }
  GlBuffer(GlBuffer&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlBuffer& operator=(GlBuffer&& other) noexcept {
    std::swap(id_, other.id_);
    return *this;
  }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

class GlVertexArray {
 public:
  GlVertexArray() { glCreateVertexArrays(1, &id_); }
  ~GlVertexArray() { if (id_ != 0) glDeleteVertexArrays(1, &id_); }
  GlVertexArray(GlVertexArray&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlVertexArray& operator=(GlVertexArray&& other) noexcept {
    std::swap(id_, other.id_);
    return *this;
  }
  GLuint id() const { return id_; }
  void Bind() const { glBindVertexArray(id_); }

 private:
  GLuint id_ = 0;
};

struct TextureOptions {
  bool srgb = true;      // 8-bit colour is sRGB-encoded: sample as linear
  bool mipmaps = true;
  bool repeat = true;    // else clamp to edge
};

class GlTexture {
 public:
  GlTexture() = default;
  // Uploads a 1-4 channel 8-bit image (top row at t = 0, as image files are stored).
  GlTexture(const Image8& image, const TextureOptions& options);
  ~GlTexture() { if (id_ != 0) glDeleteTextures(1, &id_); }
  GlTexture(GlTexture&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlTexture& operator=(GlTexture&& other) noexcept {
    std::swap(id_, other.id_);
    return *this;
  }
  GLuint id() const { return id_; }
  void Bind(int unit) const { glBindTextureUnit(static_cast<GLuint>(unit), id_); }

 private:
  GLuint id_ = 0;
};

}  // namespace voltree
