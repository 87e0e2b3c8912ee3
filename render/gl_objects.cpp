#include "render/gl_objects.h"

#include <algorithm>
#include <bit>

#include "core/error.h"
#include "render/gl_context.h"

namespace voltree {

GlBuffer::GlBuffer(const void* data, size_t bytes) {
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 1)), bytes > 0 ? data : nullptr, 0);
  CheckGl("uploading a buffer");
}

GlTexture::GlTexture(const Image8& image, const TextureOptions& options) {
  if (image.empty() || image.channels < 1 || image.channels > 4)
    Fail("texture upload: expected a non-empty image with 1 to 4 channels, got ", image.width, "x",
         image.height, "x", image.channels);
  // Single-channel textures are replicated to RGB by swizzling, not by copying.
  static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  const GLenum format = kFormats[image.channels - 1];
  GLenum internal = GL_RGBA8;
  if (image.channels <= 2) internal = image.channels == 1 ? GL_R8 : GL_RG8;
  else if (options.srgb) internal = image.channels == 3 ? GL_SRGB8 : GL_SRGB8_ALPHA8;
  else internal = image.channels == 3 ? GL_RGB8 : GL_RGBA8;
  const int levels = options.mipmaps ? std::bit_width(static_cast<unsigned>(std::max(image.width, image.height))) : 1;
  glCreateTextures(GL_TEXTURE_2D, 1, &id_);
  glTextureStorage2D(id_, levels, internal, image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(id_, 0, 0, 0, image.width, image.height, format, GL_UNSIGNED_BYTE, image.pixels.data());
  if (options.mipmaps) glGenerateTextureMipmap(id_);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, options.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint wrap = options.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, wrap);
  if (image.channels == 1) {
    const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTextureParameteriv(id_, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  }
  CheckGl("uploading a texture");
}

}  // namespace voltree
