#include "render/ground_renderer.h"

#include <string>

#include "render/gl.h"
#include "render/gl_context.h"

namespace voltree {
namespace {

// A grid of kGroundCells^2 quads generated from gl_VertexID (no buffers), fine enough that
// per-vertex lens distortion bends it like the billboards.
constexpr int kGroundCells = 32;

constexpr const char* kGroundMain = R"(
uniform vec2 uGroundMin, uGroundSize;
uniform int uCells;
void main() {
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  int cell = gl_VertexID / 6;
  ivec2 ij = ivec2(cell % uCells, cell / uCells) + corners[gl_VertexID % 6];
  gl_Position = ProjectToClip(vec3(uGroundMin + uGroundSize * vec2(ij) / float(uCells), 0.0));
}
)";

constexpr const char* kGroundFragment = R"(#version 430 core
uniform vec3 uColour;
out vec4 color;
void main() { color = vec4(uColour, 1.0); }
)";

}  // namespace

GroundRenderer::GroundRenderer()
    : program_(ShaderProgram::Graphics(
          "scene ground", std::string("#version 430 core\n") + kProjectionGlsl + kGroundMain, kGroundFragment)) {
  CheckGl("render: creating the scene's ground");
}

void GroundRenderer::Draw(const View& view, const DepthRange& depth, const SceneGround& ground,
                          const Eigen::Vector3f& colour) const {
  SetProjectionUniforms(program_, view, depth);
  program_.Set("uGroundMin", Eigen::Vector2f((ground.centre - 0.5 * ground.size).cast<float>()));
  program_.Set("uGroundSize", Eigen::Vector2f(ground.size.cast<float>()));
  program_.Set("uCells", kGroundCells);
  program_.Set("uColour", colour);
  program_.Use();
  vertex_array_.Bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // seen from below it is still the ground
  glDrawArrays(GL_TRIANGLES, 0, 6 * kGroundCells * kGroundCells);
  glBindVertexArray(0);
}

}  // namespace voltree
