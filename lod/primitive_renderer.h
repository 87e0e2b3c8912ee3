// Draws the primitives that replace polygons in the distant levels of detail: points (square
// splats of a given size in pixels), shaded closed surfaces (ellipsoids) and lines (screen-space quads of two triangles
// as wide as the branch they stand for, never thinner than a given width), lit with the studio's light as
// StudioTreeRenderer lights its leaves and bark, so that their images compare with the full mesh's.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "render/gl_objects.h"
#include "render/shader.h"
#include "samples/studio_lighting.h"

namespace voltree {

struct PointPrimitive {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  Eigen::Vector3f colour = Eigen::Vector3f::Ones();  // linear RGB, texture and tint included
};

struct LinePrimitive {
  Eigen::Vector3f a = Eigen::Vector3f::Zero(), b = Eigen::Vector3f::Zero();
  Eigen::Vector3f colour = Eigen::Vector3f::Ones();  // linear RGB
  float width = 0;                                   // world units (the branch's diameter)
};

struct PrimitiveDrawOptions {
  float point_pixels = 1;     // side of each point splat, in output pixels (supersampling aside)
  float min_line_pixels = 1;  // lines are at least this wide, in output pixels
};

class PrimitiveRenderer {
 public:
  // Uploads the primitives once; needs a current GL context. `crown_min/max`: the box of the
  // leaves, for the studio shader's self-shadowing of the crown. `surface`: triangles, three
  // corners each, with outward normals (lit from the front only).
  PrimitiveRenderer(const std::vector<PointPrimitive>& points, const std::vector<LinePrimitive>& lines,
                    const Eigen::Vector3f& crown_min, const Eigen::Vector3f& crown_max,
                    const std::vector<PointPrimitive>& surface = {});

  // Draws into the bound target with depth testing (the viewport's height over the camera's is
  // taken as the supersampling).
  void Draw(const View& view, const StudioLighting& lighting, double near, double far,
            const PrimitiveDrawOptions& options) const;

  size_t GpuBytes() const {
    return point_buffer_.bytes() + line_buffer_.bytes() + line_indices_.bytes() + surface_buffer_.bytes();
  }

 private:
  size_t point_count_ = 0, line_count_ = 0, surface_count_ = 0;
  GlBuffer point_buffer_, line_buffer_, line_indices_, surface_buffer_;
  GlVertexArray point_array_, line_array_, surface_array_;
  ShaderProgram point_program_, line_program_;
  Eigen::Vector3f crown_center_, crown_radii_;
};

}  // namespace voltree
