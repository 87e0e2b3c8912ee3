#include "render/shader.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/gl_context.h"

namespace voltree {
namespace {

constexpr const char* kVertex = R"(#version 430 core
void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }
)";

TEST(ShaderProgram, CompilesAndFindsUniforms) {
  GlContext context;
  const ShaderProgram program = ShaderProgram::Graphics("ok", kVertex, R"(#version 430 core
uniform vec4 uColor;
out vec4 color;
void main() { color = uColor; }
)");
  EXPECT_NE(program.id(), 0u);
  EXPECT_GE(program.Location("uColor"), 0);
  EXPECT_EQ(program.Location("uMissing"), -1);
}

TEST(ShaderProgram, SyntaxErrorQuotesTheSourceLine) {
  GlContext context;
  try {
    ShaderProgram::Graphics("broken", kVertex, R"(#version 430 core
out vec4 color;
void main() {
  vec3 tint = vec3(1.0) +;
  color = vec4(tint, 1.0);
}
)");
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken"), std::string::npos) << message;
    EXPECT_NE(message.find("fragment"), std::string::npos) << message;
    // The offending line, with its number and a marker.
    EXPECT_NE(message.find(">   4 |   vec3 tint = vec3(1.0) +;"), std::string::npos) << message;
  }
}

TEST(ShaderProgram, QuotesLinesFromMesaAndNvidiaLogs) {
  const std::string source = "a\nb\nc\nd\n";
  EXPECT_EQ(QuoteShaderLines(source, "0:3(7): error: x"), "    2 | b\n>   3 | c\n    4 | d\n");
  EXPECT_EQ(QuoteShaderLines(source, "0(1) : error C0000: y"), ">   1 | a\n    2 | b\n");
  EXPECT_EQ(QuoteShaderLines(source, "no line numbers here"), "");
}

TEST(ShaderProgram, ComputeShaderCompiles) {
  GlContext context;
  const ShaderProgram program = ShaderProgram::Compute("compute", R"(#version 430 core
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Data { uint value; };
void main() { value = 42u; }
)");
  EXPECT_NE(program.id(), 0u);
}

}  // namespace
}  // namespace voltree
