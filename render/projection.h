// The camera projection shared by every shader that draws into a voltree frame (billboards, the
// scene's ground): window coordinates are COLMAP pixel coordinates, lens distortion per vertex,
// and one depth range per frame so that separately drawn objects depth-test against each other.
#pragma once

#include <Eigen/Core>

#include "core/camera.h"
#include "render/shader.h"

namespace voltree {

// Distances from the eye along the view axis mapped to depth 0 and 1 (near > 0, far > near).
struct DepthRange {
  double near = 0.01, far = 100;
  void Check() const;
};

// A range that holds a sphere seen from `eye` (the sphere may contain the eye).
DepthRange DepthRangeForSphere(const Eigen::Vector3d& eye, const Eigen::Vector3d& centre, double radius);

// GLSL (no #version): uniforms uWorldToCamera, uTranslation, uFocal, uPrincipal, uDistortion,
// uImageSize, uDepthRange and `vec4 ProjectToClip(vec3 world)`. Without distortion the clip
// position is linear in the camera-space point, so triangles crossing the camera plane clip
// correctly (the ground passes under the camera).
extern const char* const kProjectionGlsl;

// Sets those uniforms on `program` for `view`.
void SetProjectionUniforms(const ShaderProgram& program, const View& view, const DepthRange& depth);

}  // namespace voltree
