// GLSL programs: compile, link, set uniforms. Compile errors quote the driver's log and the
// offending source lines with their numbers, so a shader bug reads like a compiler error.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "render/gl.h"

namespace voltree {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Vertex + fragment program; `name` appears in error messages.
  static ShaderProgram Graphics(std::string_view name, std::string_view vertex_source,
                                std::string_view fragment_source);
  static ShaderProgram Compute(std::string_view name, std::string_view compute_source);

  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  void Use() const;
  // -1 when the uniform does not exist or was optimized away (setting it is then a no-op).
  GLint Location(const char* name) const;

  void Set(const char* name, int value) const;
  void Set(const char* name, float value) const;
  void Set(const char* name, const Eigen::Vector2f& value) const;
  void Set(const char* name, const Eigen::Vector3f& value) const;
  void Set(const char* name, const Eigen::Vector4f& value) const;
  void Set(const char* name, const Eigen::Matrix3f& value) const;
  void Set(const char* name, const Eigen::Matrix4f& value) const;

 private:
  explicit ShaderProgram(GLuint program) : program_(program) {}
  GLuint program_ = 0;
};

// A complete vertex shader (#version 430 core) drawing one triangle that covers the viewport:
// glDrawArrays(GL_TRIANGLES, 0, 3) with no vertex buffer; fragment shaders use gl_FragCoord.
extern const char* const kFullScreenTriangleVertexShader;

// "  12 | vec3 x = ;" lines of `source` around each line that the driver's `log` names
// (Mesa "0:12(5): error", NVIDIA "0(12) : error"); exposed for tests.
std::string QuoteShaderLines(std::string_view source, std::string_view log);

}  // namespace voltree
