#include "render/box_filter.h"

#include "core/error.h"
#include "render/gl_context.h"

namespace voltree {
namespace {

constexpr const char* kFragment = R"(#version 430 core
uniform sampler2D uSource;
uniform int uFactor;
out vec4 outColor;
void main() {
  ivec2 origin = ivec2(gl_FragCoord.xy) * uFactor;
  vec4 sum = vec4(0.0);
  for (int y = 0; y < uFactor; ++y)
    for (int x = 0; x < uFactor; ++x) sum += texelFetch(uSource, origin + ivec2(x, y), 0);
  outColor = sum / float(uFactor * uFactor);
}
)";

}  // namespace

BoxDownsampler::BoxDownsampler()
    : program_(ShaderProgram::Graphics("box filter", kFullScreenTriangleVertexShader, kFragment)) {
  program_.Set("uSource", 0);
}

ImageF BoxDownsampler::Downsample(const Framebuffer& source, int factor) {
  if (factor < 1 || source.width() % factor != 0 || source.height() % factor != 0)
    Fail("box filter: ", source.width(), "x", source.height(), " is not a multiple of ", factor);
  const int width = source.width() / factor, height = source.height() / factor;
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<Framebuffer>(width, height, ColorFormat::kRGBA32F, false);
  target_->Bind();
  program_.Set("uFactor", factor);
  program_.Use();
  glBindTextureUnit(0, source.color_texture());
  empty_vertex_array_.Bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  CheckGl("box filtering");
  return target_->ReadImageF();
}

}  // namespace voltree
