// Which leaf each pixel sees: every leaf drawn in its own colour (its index + 1), alpha-tested
// against its material like the studio's renderer, the bark in colour 0 so that it hides what is
// behind it; one sample per pixel. The per-leaf pixel counts are the projected areas of
// viewpoint mutual information (the "hybrid histogram" of the VMI papers).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "lod/leaf_separation.h"
#include "render/framebuffer.h"
#include "render/gl_objects.h"
#include "render/shader.h"
#include "samples/tree_mesh.h"

namespace voltree {

class LeafIdRenderer {
 public:
  // Needs a current GL context. Throws Error for more than 2^24 - 1 leaves.
  LeafIdRenderer(const TreeMesh& mesh, const std::vector<Leaf>& leaves);

  // Visible pixels of each leaf (indexed like `leaves`) in `view`, drawing the bark and the leaves
  // whose `drawn` entry is not 0.
  std::vector<uint32_t> VisiblePixels(const View& view, const std::vector<uint8_t>& drawn);

 private:
  struct Range {  // one material's triangles: bark, or the leaves of one group
    int material = 0;
    bool leafy = false;
    std::vector<uint32_t> first_vertex_of_leaf;  // leafy: where each leaf's vertices start
    std::vector<uint32_t> leaf_index;            // leafy: the leaf of each entry above
    std::vector<uint32_t> vertex_count_of_leaf;
    uint32_t first_vertex = 0, vertex_count = 0;  // bark
  };
  size_t leaf_count_;
  std::vector<Material> materials_;
  std::vector<GlTexture> textures_;
  std::vector<Range> ranges_;
  GlBuffer vertices_;
  GlVertexArray vertex_array_;
  ShaderProgram program_;
  Eigen::Vector3d bounds_min_, bounds_max_;
  std::unique_ptr<Framebuffer> target_;
};

}  // namespace voltree
