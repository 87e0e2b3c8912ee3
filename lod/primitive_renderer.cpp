#include "lod/primitive_renderer.h"

#include <algorithm>
#include <string>
#include <tuple>

#include "render/gl.h"
#include "render/gl_context.h"
#include "samples/studio_projection.h"
#include "samples/studio_shading.h"

namespace voltree {
namespace {

constexpr const char* kPointVertex = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform float uPointSize;  // framebuffer pixels (points only)
out vec3 vWorld;
out vec3 vNormal;
out vec3 vColour;
void main() {
  vWorld = aPosition;
  vNormal = aNormal;
  vColour = aColour;
  gl_Position = ProjectToClip(aPosition);
  gl_PointSize = uPointSize;
}
)";

constexpr const char* kPointFragment = R"(
layout(early_fragment_tests) in;
in vec3 vWorld;
in vec3 vNormal;
in vec3 vColour;
uniform int uDoubleSided;  // points are leaves, seen from both sides; surfaces are closed
out vec4 outColor;
void main() {
  vec3 normal = normalize(vNormal);
  if (uDoubleSided != 0 && dot(normal, CameraCenter() - vWorld) < 0.0) normal = -normal;
  outColor = vec4(Shade(vColour, vWorld, normal, uDoubleSided != 0), 1.0);
}
)";

// Each line is a quad across the screen (GL's wide lines are not in the core profile): its four
// corners carry both ends, and each moves its own end sideways by half the width the branch
// projects to (w = width * f / z), at least uMinWidth.
constexpr const char* kLineVertex = R"(
layout(location = 0) in vec3 aSelf;   // this corner's end of the line
layout(location = 1) in vec3 aOther;  // the other end
layout(location = 2) in vec3 aColour;
layout(location = 3) in vec2 aWidthSide;  // world width; side -1 or +1, negated at the far end
uniform vec2 uViewport;     // framebuffer pixels
uniform float uPixelScale;  // framebuffer pixels per image pixel (the supersampling)
uniform float uMinWidth;    // framebuffer pixels
out vec3 vWorld;
out vec3 vColour;
out vec3 vAxis;
void main() {
  vec4 self = ProjectToClip(aSelf), other = ProjectToClip(aOther);
  vWorld = aSelf;
  vColour = aColour;
  vAxis = aOther - aSelf;
  vec2 d = (other.xy / max(other.w, 1e-6) - self.xy / max(self.w, 1e-6)) * uViewport;
  if (dot(d, d) < 1e-12) d = vec2(1.0, 0.0);
  vec2 across = normalize(vec2(-d.y, d.x));
  float width = max(aWidthSide.x * uFocal.y * uPixelScale / max(self.w, 1e-6), uMinWidth);
  gl_Position = self + vec4(aWidthSide.y * across * width / uViewport * self.w, 0.0, 0.0);
}
)";

// A branch is a cylinder: its normal towards the viewer is the view direction less its axis part.
constexpr const char* kLineFragment = R"(
layout(early_fragment_tests) in;
in vec3 vWorld;
in vec3 vColour;
in vec3 vAxis;
out vec4 outColor;
void main() {
  vec3 to_camera = normalize(CameraCenter() - vWorld);
  vec3 axis = length(vAxis) > 0.0 ? normalize(vAxis) : vec3(0.0, 0.0, 1.0);
  vec3 normal = to_camera - dot(to_camera, axis) * axis;
  normal = length(normal) > 1e-4 ? normalize(normal) : to_camera;
  outColor = vec4(Shade(vColour, vWorld, normal, false), 1.0);
}
)";

struct PackedPoint {
  float position[3];
  float normal[3];
  float colour[3];
};

struct PackedCorner {
  float self[3];
  float other[3];
  float colour[3];
  float width_side[2];
};

struct Attribute {
  GLuint location;
  GLint size;
  GLuint offset;
};

void Bind(const GlVertexArray& array, const GlBuffer& buffer, size_t stride, std::initializer_list<Attribute> list) {
  const GLuint vao = array.id();
  glVertexArrayVertexBuffer(vao, 0, buffer.id(), 0, static_cast<GLsizei>(stride));
  for (const Attribute& attribute : list) {
    glEnableVertexArrayAttrib(vao, attribute.location);
    glVertexArrayAttribFormat(vao, attribute.location, attribute.size, GL_FLOAT, GL_FALSE, attribute.offset);
    glVertexArrayAttribBinding(vao, attribute.location, 0);
  }
}

void SetLight(const ShaderProgram& program, const StudioLighting& lighting, const Eigen::Vector3f& centre,
              const Eigen::Vector3f& radii) {
  program.Set("uSunDirection", lighting.sun_direction);
  program.Set("uSunColor", lighting.sun_color);
  program.Set("uSkyAmbient", lighting.sky_ambient);
  program.Set("uGroundAmbient", lighting.ground_ambient);
  program.Set("uCrownCenter", centre);
  program.Set("uCrownRadii", radii);
}

}  // namespace

PrimitiveRenderer::PrimitiveRenderer(const std::vector<PointPrimitive>& points, const std::vector<LinePrimitive>& lines,
                                     const Eigen::Vector3f& crown_min, const Eigen::Vector3f& crown_max,
                                     const std::vector<PointPrimitive>& surface)
    : point_count_(points.size()),
      line_count_(lines.size()),
      surface_count_(surface.size()),
      crown_center_(0.5f * (crown_min + crown_max)),
      crown_radii_((0.5f * (crown_max - crown_min)).cwiseMax(1e-3f)) {
  const auto pack = [](const std::vector<PointPrimitive>& list) {
    std::vector<PackedPoint> packed;
    packed.reserve(list.size());
    for (const PointPrimitive& p : list)
      packed.push_back({{p.position.x(), p.position.y(), p.position.z()},
                        {p.normal.x(), p.normal.y(), p.normal.z()},
                        {p.colour.x(), p.colour.y(), p.colour.z()}});
    return packed;
  };
  const std::vector<PackedPoint> packed_points = pack(points), packed_surface = pack(surface);
  std::vector<PackedCorner> corners;
  std::vector<uint32_t> indices;
  corners.reserve(4 * lines.size());
  indices.reserve(6 * lines.size());
  for (const LinePrimitive& l : lines) {
    const auto base = static_cast<uint32_t>(corners.size());
    // Seen from the far end the screen direction is reversed, and so is the side.
    for (const auto& [self, other, side] :
         {std::tuple{l.a, l.b, -1.f}, std::tuple{l.a, l.b, 1.f}, std::tuple{l.b, l.a, 1.f}, std::tuple{l.b, l.a, -1.f}})
      corners.push_back({{self.x(), self.y(), self.z()},
                         {other.x(), other.y(), other.z()},
                         {l.colour.x(), l.colour.y(), l.colour.z()},
                         {l.width, side}});
    indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  point_buffer_ = GlBuffer(packed_points.data(), packed_points.size() * sizeof(PackedPoint));
  surface_buffer_ = GlBuffer(packed_surface.data(), packed_surface.size() * sizeof(PackedPoint));
  line_buffer_ = GlBuffer(corners.data(), corners.size() * sizeof(PackedCorner));
  line_indices_ = GlBuffer(indices.data(), indices.size() * sizeof(uint32_t));
  for (const auto& [array, buffer] : {std::pair{&point_array_, &point_buffer_}, {&surface_array_, &surface_buffer_}})
    Bind(*array, *buffer, sizeof(PackedPoint),
         {{0, 3, offsetof(PackedPoint, position)},
          {1, 3, offsetof(PackedPoint, normal)},
          {2, 3, offsetof(PackedPoint, colour)}});
  Bind(line_array_, line_buffer_, sizeof(PackedCorner),
       {{0, 3, offsetof(PackedCorner, self)},
        {1, 3, offsetof(PackedCorner, other)},
        {2, 3, offsetof(PackedCorner, colour)},
        {3, 2, offsetof(PackedCorner, width_side)}});
  glVertexArrayElementBuffer(line_array_.id(), line_indices_.id());
  const std::string header = std::string("#version 430 core\n") + kStudioProjectionGlsl;
  point_program_ =
      ShaderProgram::Graphics("lod points", header + kPointVertex, header + kStudioShadeGlsl + kPointFragment);
  line_program_ = ShaderProgram::Graphics("lod lines", header + kLineVertex, header + kStudioShadeGlsl + kLineFragment);
  CheckGl("uploading points and lines");
}

void PrimitiveRenderer::Draw(const View& view, const StudioLighting& lighting, double near, double far,
                             const PrimitiveDrawOptions& options) const {
  GLint viewport[4] = {0, 0, 1, 1};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const float pixel_scale = static_cast<float>(viewport[3]) / static_cast<float>(std::max(view.camera.height, 1));
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (point_count_ > 0 || surface_count_ > 0) {
    SetStudioCamera(point_program_, view, near, far);
    SetLight(point_program_, lighting, crown_center_, crown_radii_);
    point_program_.Use();
  }
  if (surface_count_ > 0) {
    point_program_.Set("uDoubleSided", 0);
    surface_array_.Bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(surface_count_));
  }
  if (point_count_ > 0) {
    point_program_.Set("uDoubleSided", 1);
    point_program_.Set("uPointSize", std::max(1.0f, options.point_pixels * pixel_scale));
    glEnable(GL_PROGRAM_POINT_SIZE);
    point_array_.Bind();
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(point_count_));
  }
  if (line_count_ > 0) {
    SetStudioCamera(line_program_, view, near, far);
    SetLight(line_program_, lighting, crown_center_, crown_radii_);
    line_program_.Use();
    line_program_.Set("uViewport", Eigen::Vector2f(static_cast<float>(viewport[2]), static_cast<float>(viewport[3])));
    line_program_.Set("uPixelScale", pixel_scale);
    line_program_.Set("uMinWidth", options.min_line_pixels * pixel_scale);
    line_array_.Bind();
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(6 * line_count_), GL_UNSIGNED_INT, nullptr);
  }
  CheckGl("drawing points and lines");
}

}  // namespace voltree
