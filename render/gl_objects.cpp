#include "render/gl_objects.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "render/gl_context.h"

namespace voltree {

GlBuffer::GlBuffer(const void* data, size_t bytes, size_t min_bytes)
    : name_(GlBufferName::Create()), bytes_(std::max({bytes, min_bytes, size_t(1)})) {
  std::vector<char> padded;
  if (bytes > 0 && bytes < bytes_) {
    padded.assign(bytes_, 0);
    std::memcpy(padded.data(), data, bytes);
    data = padded.data();
  }
  glNamedBufferStorage(id(), static_cast<GLsizeiptr>(bytes_), bytes > 0 ? data : nullptr, 0);
  CheckGl("uploading a buffer");
}

void GlStreamBuffer::Upload(const void* data, size_t bytes) {
  if (bytes > capacity_) {
    capacity_ = std::max(bytes, std::min(2 * capacity_, most_bytes_));
    name_ = GlBufferName::Create();
    glNamedBufferData(id(), static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
  }
  glNamedBufferSubData(id(), 0, static_cast<GLsizeiptr>(bytes), data);
}

GlTexture::GlTexture(const Image8& image, const TextureOptions& options) {
  if (image.empty() || image.channels < 1 || image.channels > 4)
    Fail("texture upload: expected a non-empty image with 1 to 4 channels, got ", image.width, "x", image.height, "x",
         image.channels);
  // Single-channel textures are replicated to RGB by swizzling, not by copying.
  static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  const GLenum format = kFormats[image.channels - 1];
  GLenum internal = GL_RGBA8;
  if (image.channels <= 2)
    internal = image.channels == 1 ? GL_R8 : GL_RG8;
  else if (options.srgb)
    internal = image.channels == 3 ? GL_SRGB8 : GL_SRGB8_ALPHA8;
  else
    internal = image.channels == 3 ? GL_RGB8 : GL_RGBA8;
  const int levels = options.mipmaps ? std::bit_width(static_cast<unsigned>(std::max(image.width, image.height))) : 1;
  name_ = GlTextureName::Create();
  const GLuint texture = name_.id();
  glTextureStorage2D(texture, levels, internal, image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture, 0, 0, 0, image.width, image.height, format, GL_UNSIGNED_BYTE, image.pixels.data());
  if (options.mipmaps) glGenerateTextureMipmap(texture);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, options.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint wrap = options.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, wrap);
  if (image.channels == 1) {
    const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTextureParameteriv(texture, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  }
  CheckGl("uploading a texture");
}

GlTexture GlTexture::Dxt5(int width, int height, std::span<const uint8_t> blocks, const char* what) {
  GlTexture texture;
  texture.name_ = GlTextureName::Create();
  const GLuint id = texture.id();
  glTextureStorage2D(id, 1, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, width, height);
  glCompressedTextureSubImage2D(id, 0, 0, 0, width, height, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
                                static_cast<GLsizei>(blocks.size()), blocks.data());
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  CheckGl(what);
  return texture;
}

}  // namespace voltree
