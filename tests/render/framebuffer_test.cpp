#include "render/framebuffer.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"
#include "render/shader.h"

namespace voltree {
namespace {

TEST(Framebuffer, ClearColourReadsBackExactly) {
  GlContext context;
  Framebuffer target(7, 5, ColorFormat::kRGBA8);
  target.Clear(64 / 255.0f, 128 / 255.0f, 1.0f, 3 / 255.0f);
  const Image8 image = target.ReadImage8();
  ASSERT_EQ(image.width, 7);
  ASSERT_EQ(image.height, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) {
      EXPECT_EQ(image.at(x, y, 0), 64);
      EXPECT_EQ(image.at(x, y, 1), 128);
      EXPECT_EQ(image.at(x, y, 2), 255);
      EXPECT_EQ(image.at(x, y, 3), 3);
    }
  Framebuffer float_target(3, 2, ColorFormat::kRGBA32F);
  float_target.Clear(0.125f, -2.0f, 7.5f, 0.25f);
  const ImageF values = float_target.ReadImageF();
  EXPECT_EQ(values.at(2, 1, 0), 0.125f);
  EXPECT_EQ(values.at(2, 1, 1), -2.0f);
  EXPECT_EQ(values.at(0, 0, 2), 7.5f);
  EXPECT_EQ(values.at(0, 0, 3), 0.25f);
}

// A triangle covering the upper-left half of NDC must appear in the upper-left of the image
// (images are read back top row first).
TEST(Framebuffer, TriangleDrawsWhereExpected) {
  GlContext context;
  const ShaderProgram program = ShaderProgram::Graphics("triangle", R"(#version 430 core
layout(location = 0) in vec2 aPosition;
void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }
)",
                                                        R"(#version 430 core
out vec4 color;
void main() { color = vec4(1.0, 0.5, 0.0, 1.0); }
)");
  // Upper-left half: vertices (-1,-1), (1,1), (-1,1).
  const float vertices[] = {-1, -1, 1, 1, -1, 1};
  GlBuffer buffer(vertices, sizeof(vertices));
  GlVertexArray vertex_array;
  glVertexArrayVertexBuffer(vertex_array.id(), 0, buffer.id(), 0, 2 * sizeof(float));
  glEnableVertexArrayAttrib(vertex_array.id(), 0);
  glVertexArrayAttribFormat(vertex_array.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array.id(), 0, 0);

  constexpr int kSize = 16;
  Framebuffer target(kSize, kSize, ColorFormat::kRGBA8);
  target.Bind();
  target.Clear(0, 0, 0, 0);
  program.Use();
  vertex_array.Bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  CheckGl("drawing");
  const Image8 image = target.ReadImage8();
  int covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool inside = image.at(x, y, 3) == 255;
      covered += inside;
      // The diagonal runs from the bottom-left to the top-right corner: x + y = size in pixels.
      if (x + y > kSize - 1) {
        EXPECT_FALSE(inside) << x << "," << y;
      }
      if (x + y < kSize - 1) {
        EXPECT_TRUE(inside) << x << "," << y;
        EXPECT_EQ(image.at(x, y, 0), 255);
        EXPECT_EQ(image.at(x, y, 1), 128);
        EXPECT_EQ(image.at(x, y, 2), 0);
      }
    }
  // The diagonal pixels' centres lie exactly on the edge; the fill rule takes half or all of them.
  EXPECT_GE(covered, kSize * (kSize - 1) / 2);
  EXPECT_LE(covered, kSize * (kSize + 1) / 2);
}

TEST(Framebuffer, RejectsBadSize) {
  GlContext context;
  EXPECT_THROW(Framebuffer(0, 4, ColorFormat::kRGBA8), Error);
  EXPECT_THROW(Framebuffer(1 << 20, 4, ColorFormat::kRGBA8), Error);
}

}  // namespace
}  // namespace voltree
