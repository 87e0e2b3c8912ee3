// Draws a TreeMesh with the studio's cameras and light: textured, alpha-tested leaves lit from
// both sides, Lambertian bark, sky ambient; colour in linear RGB with alpha 1 where covered.
// A depth pass (alpha test only) comes first so that the shading pass runs once per sample.
#pragma once

#include <vector>

#include "core/camera.h"
#include "render/framebuffer.h"
#include "render/gl_objects.h"
#include "render/shader.h"
#include "samples/studio_lighting.h"
#include "samples/tree_mesh.h"

namespace voltree {

class StudioTreeRenderer {
 public:
  // Uploads the mesh and its textures once; needs a current GL context.
  explicit StudioTreeRenderer(const TreeMesh& mesh);

  // Draws into the bound `target` (cleared by the caller) with depth testing. `parts`: the
  // visible surface flat red where it is bark and green where it is a leaf, instead of shaded.
  void Draw(const View& view, const StudioLighting& lighting, double near, double far, bool parts = false) const;

 private:
  void DrawGroups(const ShaderProgram& program, bool depth_only, bool parts) const;

  struct Group {
    int material = 0;
    size_t first_index = 0;
    size_t index_count = 0;
  };
  std::vector<Material> materials_;
  std::vector<Group> groups_;
  std::vector<GlTexture> textures_;
  GlBuffer vertices_, indices_;
  GlVertexArray vertex_array_;
  ShaderProgram depth_program_, program_;
  Eigen::Vector3f crown_center_, crown_radii_;
};

}  // namespace voltree
