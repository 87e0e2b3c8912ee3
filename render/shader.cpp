#include "render/shader.h"

#include <regex>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/error.h"

namespace voltree {

const char* const kFullScreenTriangleVertexShader = R"(#version 430 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
namespace {

std::vector<std::string> SplitLines(std::string_view text) {
  std::vector<std::string> lines;
  std::istringstream in{std::string(text)};
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string InfoLog(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  if (is_program)
    glGetProgramInfoLog(object, length, nullptr, log.data());
  else
    glGetShaderInfoLog(object, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

const char* StageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_COMPUTE_SHADER:
      return "compute";
    default:
      return "shader";
  }
}

GLuint CompileStage(std::string_view name, GLenum stage, std::string_view source) {
  const GLuint shader = glCreateShader(stage);
  if (shader == 0) Fail("OpenGL: cannot create a ", StageName(stage), " shader for '", name, "'");
  const char* text = source.data();
  const GLint length = static_cast<GLint>(source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = InfoLog(shader, false);
    glDeleteShader(shader);
    Fail("shader '", name, "' (", StageName(stage), "): compilation failed:\n", log, "\n",
         QuoteShaderLines(source, log));
  }
  return shader;
}

GLuint Link(std::string_view name, const std::vector<GLuint>& shaders) {
  const GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  for (GLuint shader : shaders) {
    glDetachShader(program, shader);
    glDeleteShader(shader);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = InfoLog(program, true);
    glDeleteProgram(program);
    Fail("shader '", name, "': linking failed:\n", log);
  }
  return program;
}

}  // namespace

std::string QuoteShaderLines(std::string_view source, std::string_view log) {
  // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error C1008: ...". Source string 0 only.
  static const std::regex kLineReference(R"((?:^|\n)\s*\d+[:(](\d+)[(): ])");
  std::set<int> wanted;
  const std::string log_text(log);
  for (auto it = std::sregex_iterator(log_text.begin(), log_text.end(), kLineReference); it != std::sregex_iterator();
       ++it)
    wanted.insert(std::stoi((*it)[1].str()));
  const std::vector<std::string> lines = SplitLines(source);
  std::string quote;
  for (int line : wanted) {
    if (line < 1 || line > static_cast<int>(lines.size())) continue;
    for (int context = std::max(1, line - 1); context <= std::min<int>(lines.size(), line + 1); ++context)
      quote += Str(context == line ? ">" : " ",
                   context < 10    ? "   "
                   : context < 100 ? "  "
                                   : " ",
                   context, " | ", lines[context - 1], "\n");
  }
  return quote;
}

ShaderProgram ShaderProgram::Graphics(std::string_view name, std::string_view vertex_source,
                                      std::string_view fragment_source) {
  const GLuint vertex = CompileStage(name, GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = CompileStage(name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  return ShaderProgram(Link(name, {vertex, fragment}));
}

ShaderProgram ShaderProgram::Compute(std::string_view name, std::string_view compute_source) {
  return ShaderProgram(Link(name, {CompileStage(name, GL_COMPUTE_SHADER, compute_source)}));
}

ShaderProgram::~ShaderProgram() {
  if (program_ != 0) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : program_(std::exchange(other.program_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (program_ != 0) glDeleteProgram(program_);
    program_ = std::exchange(other.program_, 0);
  }
  return *this;
}

void ShaderProgram::Use() const { glUseProgram(program_); }

GLint ShaderProgram::Location(const char* name) const { return glGetUniformLocation(program_, name); }

void ShaderProgram::Set(const char* name, int value) const { glProgramUniform1i(program_, Location(name), value); }
void ShaderProgram::Set(const char* name, float value) const { glProgramUniform1f(program_, Location(name), value); }
void ShaderProgram::Set(const char* name, const Eigen::Vector2f& v) const {
  glProgramUniform2f(program_, Location(name), v.x(), v.y());
}
void ShaderProgram::Set(const char* name, const Eigen::Vector3f& v) const {
  glProgramUniform3f(program_, Location(name), v.x(), v.y(), v.z());
}
void ShaderProgram::Set(const char* name, const Eigen::Vector4f& v) const {
  glProgramUniform4f(program_, Location(name), v.x(), v.y(), v.z(), v.w());
}
// Eigen is column-major like GLSL, so no transpose.
void ShaderProgram::Set(const char* name, const Eigen::Matrix3f& m) const {
  glProgramUniformMatrix3fv(program_, Location(name), 1, GL_FALSE, m.data());
}
void ShaderProgram::Set(const char* name, const Eigen::Matrix4f& m) const {
  glProgramUniformMatrix4fv(program_, Location(name), 1, GL_FALSE, m.data());
}

}  // namespace voltree
