#include "samples/studio_tree_renderer.h"

#include <string>

#include "core/error.h"
#include "core/srgb.h"
#include "render/gl_context.h"
#include "samples/studio_projection.h"
#include "samples/studio_shading.h"

namespace voltree {
namespace {

constexpr const char* kVertexMain = R"(
invariant gl_Position;  // both passes must produce bit-identical depths for GL_EQUAL
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec3 aTint;
out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
out vec3 vTint;
void main() {
  vWorld = aPosition;
  vNormal = aNormal;
  vUv = aUv;
  vTint = aTint;
  gl_Position = ProjectToClip(aPosition);
}
)";

// Compiled twice: DEPTH_ONLY (the alpha test, writing depth) and the shading pass, which runs
// once per visible sample thanks to the depth test before shading.
constexpr const char* kFragment = R"(
#if !DEPTH_ONLY
layout(early_fragment_tests) in;
#endif
in vec3 vWorld;
in vec3 vNormal;
in vec2 vUv;
in vec3 vTint;
out vec4 outColor;

uniform vec3 uCameraCenter;
uniform sampler2D uTexture;
uniform int uHasTexture;
uniform vec4 uBaseColor;     // linear RGB, alpha
uniform float uAlphaCutoff;  // < 0: opaque
uniform int uDoubleSided;
uniform int uParts;        // 1: flat part colours instead of shading (truth masks of bark and leaves)
uniform vec3 uPartColor;

void main() {
  vec4 base = uBaseColor;
  if (uHasTexture != 0) base *= texture(uTexture, vUv);
#if DEPTH_ONLY
  if (base.a < uAlphaCutoff) discard;
  outColor = vec4(0.0);
#else
  if (uParts != 0) {
    outColor = vec4(uPartColor, 1.0);
    return;
  }
  base.rgb *= vTint;

  vec3 normal = normalize(vNormal);
  vec3 to_camera = normalize(uCameraCenter - vWorld);
  // Face the viewer: leaves are cards seen from both sides, and flipped bark normals are noise.
  if (dot(normal, to_camera) < 0.0) normal = -normal;

  vec3 color = Shade(base.rgb, vWorld, normal, uDoubleSided != 0);
  outColor = vec4(color, 1.0);
#endif
}
)";

struct PackedVertex {
  float position[3];
  float normal[3];
  float uv[2];
  float tint[3];
};

}  // namespace

StudioTreeRenderer::StudioTreeRenderer(const TreeMesh& mesh) : materials_(mesh.materials) {
  mesh.Check();
  std::vector<PackedVertex> packed(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const MeshVertex& v = mesh.vertices[i];
    packed[i] = {{v.position.x(), v.position.y(), v.position.z()},
                 {v.normal.x(), v.normal.y(), v.normal.z()},
                 {v.uv.x(), v.uv.y()},
                 {v.tint.x(), v.tint.y(), v.tint.z()}};
  }
  std::vector<uint32_t> indices;
  for (const MeshGroup& group : mesh.groups) {
    groups_.push_back({group.material, indices.size(), group.indices.size()});
    indices.insert(indices.end(), group.indices.begin(), group.indices.end());
  }
  vertices_ = GlBuffer(packed.data(), packed.size() * sizeof(PackedVertex));
  indices_ = GlBuffer(indices.data(), indices.size() * sizeof(uint32_t));
  const GLuint vao = vertex_array_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(PackedVertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  const struct {
    GLuint location;
    GLint size;
    GLuint offset;
  } attributes[] = {{0, 3, offsetof(PackedVertex, position)},
                    {1, 3, offsetof(PackedVertex, normal)},
                    {2, 2, offsetof(PackedVertex, uv)},
                    {3, 3, offsetof(PackedVertex, tint)}};
  for (const auto& attribute : attributes) {
    glEnableVertexArrayAttrib(vao, attribute.location);
    glVertexArrayAttribFormat(vao, attribute.location, attribute.size, GL_FLOAT, GL_FALSE, attribute.offset);
    glVertexArrayAttribBinding(vao, attribute.location, 0);
  }
  for (const Image8& texture : mesh.textures) textures_.emplace_back(texture, TextureOptions{});

  const std::string vertex = std::string("#version 430 core\n") + kStudioProjectionGlsl + kVertexMain;
  depth_program_ =
      ShaderProgram::Graphics("studio tree depth", vertex,
                              std::string("#version 430 core\n#define DEPTH_ONLY 1\n") + kStudioShadeGlsl + kFragment);
  program_ = ShaderProgram::Graphics(
      "studio tree", vertex, std::string("#version 430 core\n#define DEPTH_ONLY 0\n") + kStudioShadeGlsl + kFragment);
  depth_program_.Set("uTexture", 0);
  program_.Set("uTexture", 0);

  const auto [lo, hi] = mesh.CrownBounds();
  crown_center_ = 0.5f * (lo + hi);
  crown_radii_ = (0.5f * (hi - lo)).cwiseMax(1e-3f);
  CheckGl("uploading the tree mesh");
}

void StudioTreeRenderer::DrawGroups(const ShaderProgram& program, bool depth_only, bool parts) const {
  program.Use();
  if (!depth_only) program.Set("uParts", parts ? 1 : 0);
  for (const Group& group : groups_) {
    const Material& material = materials_[group.material];
    const float cutoff = AlphaCutoff(material);
    // Alpha-tested materials are leaves (red: bark, green: leaves).
    if (parts) program.Set("uPartColor", cutoff < 0 ? Eigen::Vector3f(1, 0, 0) : Eigen::Vector3f(0, 1, 0));
    if (depth_only && cutoff < 0) {
      program.Set("uHasTexture", 0);  // opaque: no texture fetch needed for depth
    } else {
      program.Set("uHasTexture", material.texture >= 0 ? 1 : 0);
      if (material.texture >= 0) textures_[material.texture].Bind(0);
    }
    const Eigen::Vector4f base(SrgbToLinear(material.base_color[0]), SrgbToLinear(material.base_color[1]),
                               SrgbToLinear(material.base_color[2]), material.base_color[3]);
    program.Set("uBaseColor", base);
    program.Set("uAlphaCutoff", cutoff);
    program.Set("uDoubleSided", material.double_sided ? 1 : 0);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(group.index_count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(group.first_index * sizeof(uint32_t)));
  }
}

void StudioTreeRenderer::Draw(const View& view, const StudioLighting& lighting, double near, double far,
                              bool parts) const {
  SetStudioCamera(depth_program_, view, near, far);
  SetStudioCamera(program_, view, near, far);
  program_.Set("uSunDirection", lighting.sun_direction);
  program_.Set("uSunColor", lighting.sun_color);
  program_.Set("uSkyAmbient", lighting.sky_ambient);
  program_.Set("uGroundAmbient", lighting.ground_ambient);
  program_.Set("uCrownCenter", crown_center_);
  program_.Set("uCrownRadii", crown_radii_);
  vertex_array_.Bind();
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  // Pass 1: depth of the nearest surviving (alpha-tested) surface.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  DrawGroups(depth_program_, true, false);
  // Pass 2: shade only that surface.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_EQUAL);
  DrawGroups(program_, false, parts);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  CheckGl("drawing the tree");
}

}  // namespace voltree
