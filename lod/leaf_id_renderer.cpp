#include "lod/leaf_id_renderer.h"

#include <string>

#include "core/error.h"
#include "core/srgb.h"
#include "samples/depth_range.h"
#include "render/gl_context.h"
#include "samples/studio_projection.h"

namespace voltree {
namespace {

constexpr const char* kVertexMain = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in float aId;
out vec2 vUv;
flat out uint vId;
void main() {
  vUv = aUv;
  vId = uint(aId + 0.5);
  gl_Position = ProjectToClip(aPosition);
}
)";

constexpr const char* kFragment = R"(
in vec2 vUv;
flat in uint vId;
out vec4 outColor;
uniform sampler2D uTexture;
uniform int uHasTexture;
uniform float uBaseAlpha;
uniform float uAlphaCutoff;  // < 0: opaque
void main() {
  float alpha = uBaseAlpha;
  // The finest level: projected areas are the leaves' own, not faded by coarse mip levels.
  if (uHasTexture != 0) alpha *= textureLod(uTexture, vUv, 0.0).a;
  if (alpha < uAlphaCutoff) discard;
  outColor = vec4(float(vId & 255u), float((vId >> 8) & 255u), float((vId >> 16) & 255u), 255.0) / 255.0;
}
)";

struct IdVertex {
  float position[3];
  float uv[2];
  float id;
};

}  // namespace

LeafIdRenderer::LeafIdRenderer(const TreeMesh& mesh, const std::vector<Leaf>& leaves)
    : leaf_count_(leaves.size()), materials_(mesh.materials) {
  if (leaves.size() >= (1u << 24) - 1) Fail("lod: ", leaves.size(), " leaves are more than leaf ids can name");
  std::vector<IdVertex> vertices;
  const auto add = [&](uint32_t index, float id) {
    const MeshVertex& v = mesh.vertices[index];
    vertices.push_back({{v.position.x(), v.position.y(), v.position.z()}, {v.uv.x(), v.uv.y()}, id});
  };
  std::vector<std::vector<uint32_t>> leaves_of_group(mesh.groups.size());
  for (uint32_t i = 0; i < leaves.size(); ++i) leaves_of_group[leaves[i].group].push_back(i);
  for (size_t g = 0; g < mesh.groups.size(); ++g) {
    const MeshGroup& group = mesh.groups[g];
    Range range;
    range.material = group.material;
    range.leafy = !leaves_of_group[g].empty();
    if (!range.leafy) {
      range.first_vertex = static_cast<uint32_t>(vertices.size());
      for (uint32_t index : group.indices) add(index, 0.0f);
      range.vertex_count = static_cast<uint32_t>(group.indices.size());
    } else {
      for (uint32_t i : leaves_of_group[g]) {
        range.leaf_index.push_back(i);
        range.first_vertex_of_leaf.push_back(static_cast<uint32_t>(vertices.size()));
        for (uint32_t triangle : leaves[i].triangles)
          for (int k = 0; k < 3; ++k) add(group.indices[3 * triangle + k], static_cast<float>(i + 1));
        range.vertex_count_of_leaf.push_back(static_cast<uint32_t>(3 * leaves[i].triangles.size()));
      }
    }
    ranges_.push_back(std::move(range));
  }
  vertices_ = GlBuffer(vertices.data(), vertices.size() * sizeof(IdVertex));
  const GLuint vao = vertex_array_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(IdVertex));
  const struct {
    GLuint location;
    GLint size;
    GLuint offset;
  } attributes[] = {
      {0, 3, offsetof(IdVertex, position)}, {1, 2, offsetof(IdVertex, uv)}, {2, 1, offsetof(IdVertex, id)}};
  for (const auto& attribute : attributes) {
    glEnableVertexArrayAttrib(vao, attribute.location);
    glVertexArrayAttribFormat(vao, attribute.location, attribute.size, GL_FLOAT, GL_FALSE, attribute.offset);
    glVertexArrayAttribBinding(vao, attribute.location, 0);
  }
  for (const Image8& texture : mesh.textures) textures_.emplace_back(texture, TextureOptions{});
  program_ =
      ShaderProgram::Graphics("leaf ids", std::string("#version 430 core\n") + kStudioProjectionGlsl + kVertexMain,
                              std::string("#version 430 core\n") + kFragment);
  program_.Set("uTexture", 0);
  const auto [lo, hi] = mesh.Bounds();
  bounds_min_ = lo.cast<double>();
  bounds_max_ = hi.cast<double>();
  CheckGl("uploading the leaf ids");
}

std::vector<uint32_t> LeafIdRenderer::VisiblePixels(const View& view, const std::vector<uint8_t>& drawn) {
  if (drawn.size() != leaf_count_) Fail("lod: ", drawn.size(), " drawn flags for ", leaf_count_, " leaves");
  const int width = view.camera.width, height = view.camera.height;
  if (!target_ || target_->width() != width || target_->height() != height)
    target_ = std::make_unique<Framebuffer>(width, height, ColorFormat::kRGBA8, true);
  target_->Bind();
  target_->Clear(0, 0, 0, 0);
  const auto [near, far] = BoxDepthRange(view, bounds_min_, bounds_max_);
  SetStudioCamera(program_, view, near, far);
  program_.Use();
  vertex_array_.Bind();
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (const Range& range : ranges_) {
    const Material& material = materials_[range.material];
    program_.Set("uHasTexture", material.texture >= 0 ? 1 : 0);
    if (material.texture >= 0) textures_[material.texture].Bind(0);
    program_.Set("uBaseAlpha", material.base_color[3]);
    program_.Set("uAlphaCutoff", AlphaCutoff(material));
    if (!range.leafy) {
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(range.first_vertex), static_cast<GLsizei>(range.vertex_count));
      continue;
    }
    std::vector<GLint> firsts;
    std::vector<GLsizei> counts;
    for (size_t k = 0; k < range.leaf_index.size(); ++k)
      if (drawn[range.leaf_index[k]]) {
        firsts.push_back(static_cast<GLint>(range.first_vertex_of_leaf[k]));
        counts.push_back(static_cast<GLsizei>(range.vertex_count_of_leaf[k]));
      }
    if (!firsts.empty())
      glMultiDrawArrays(GL_TRIANGLES, firsts.data(), counts.data(), static_cast<GLsizei>(firsts.size()));
  }
  CheckGl("drawing leaf ids");
  const Image8 ids = target_->ReadImage8();
  std::vector<uint32_t> pixels(leaf_count_, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t id = ids.at(x, y, 0) | (ids.at(x, y, 1) << 8) | (ids.at(x, y, 2) << 16);
      if (id > 0 && id <= leaf_count_) ++pixels[id - 1];
    }
  return pixels;
}

}  // namespace voltree
