// Owners for OpenGL object names (buffers, vertex arrays, textures, framebuffers, renderbuffers,
// queries):
// each name is deleted once, by its owner, also when a constructor throws half way through.
// Owners are movable, not copyable.
#pragma once

#include <cstdint>
#include <span>
#include <utility>

#include "core/image.h"
#include "render/gl.h"

namespace voltree {

// One object name, or none (0), made by `kCreate` and deleted by `kDelete` (glCreateBuffers and
// glDeleteBuffers, ...).
template <void (*kCreate)(GLsizei, GLuint*), void (*kDelete)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() = default;
  static GlName Create() {
    GlName name;
    kCreate(1, &name.id_);
    return name;
  }
  ~GlName() {
    if (id_ != 0) kDelete(1, &id_);
  }
  GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    std::swap(id_, other.id_);
    return *this;
  }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

inline void CreateTextures2d(GLsizei count, GLuint* ids) { glCreateTextures(GL_TEXTURE_2D, count, ids); }

using GlBufferName = GlName<glCreateBuffers, glDeleteBuffers>;
using GlVertexArrayName = GlName<glCreateVertexArrays, glDeleteVertexArrays>;
using GlTextureName = GlName<CreateTextures2d, glDeleteTextures>;
using GlFramebufferName = GlName<glCreateFramebuffers, glDeleteFramebuffers>;
using GlRenderbufferName = GlName<glCreateRenderbuffers, glDeleteRenderbuffers>;
// glGenQueries: a query's target is fixed by its first glBeginQuery, not at creation.
using GlQueryName = GlName<glGenQueries, glDeleteQueries>;

class GlBuffer {
 public:
  GlBuffer() = default;
  // Immutable storage of max(bytes, min_bytes, 1) bytes, the first `bytes` from `data`, the rest 0.
  GlBuffer(const void* data, size_t bytes, size_t min_bytes = 1);
  GLuint id() const { return name_.id(); }
  size_t bytes() const { return bytes_; }  // allocated on the GPU

 private:
  GlBufferName name_;
  size_t bytes_ = 0;
};

// A buffer rewritten every frame (GL_STREAM_DRAW). It grows, at least doubling but never beyond
// `most_bytes` (what its owner knows a frame can need), when a frame needs more, and never shrinks,
// so frames and instances reuse it.
class GlStreamBuffer {
 public:
  explicit GlStreamBuffer(size_t most_bytes = SIZE_MAX) : most_bytes_(most_bytes) {}
  void Upload(const void* data, size_t bytes);
  GLuint id() const { return name_.id(); }
  size_t capacity() const { return capacity_; }

 private:
  GlBufferName name_;
  size_t capacity_ = 0;
  size_t most_bytes_;
};

class GlVertexArray {
 public:
  GlVertexArray() : name_(GlVertexArrayName::Create()) {}
  GLuint id() const { return name_.id(); }
  void Bind() const { glBindVertexArray(name_.id()); }

 private:
  GlVertexArrayName name_;
};

struct TextureOptions {
  bool srgb = true;  // 8-bit colour is sRGB-encoded: sample as linear
  bool mipmaps = true;
  bool repeat = true;  // else clamp to edge
};

class GlTexture {
 public:
  GlTexture() = default;
  // Uploads a 1-4 channel 8-bit image (top row at t = 0, as image files are stored).
  GlTexture(const Image8& image, const TextureOptions& options);
  // DXT5 blocks of a width x height image, linear filtering, clamped, no mipmaps. `what` names the
  // texture in errors.
  static GlTexture Dxt5(int width, int height, std::span<const uint8_t> blocks, const char* what);
  GLuint id() const { return name_.id(); }
  void Bind(int unit) const { glBindTextureUnit(static_cast<GLuint>(unit), name_.id()); }

 private:
  GlTextureName name_;
};

}  // namespace voltree
