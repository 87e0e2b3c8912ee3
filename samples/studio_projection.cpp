#include "samples/studio_projection.h"

#include "render/projection.h"

namespace voltree {

// kProjectionGlsl (render/projection.h: the uniforms, Distort and ProjectToClip) followed by the
// studio's per-pixel rays.
const std::string kStudioProjectionGlsl = std::string(kProjectionGlsl) + R"(
uniform vec3 uCameraCenter;
uniform int uHasDistortion;

// Newton's method with the analytic Jacobian; a fixed count keeps it branch-free.
vec2 Undistort(vec2 d) {
  if (uHasDistortion == 0) return d;
  vec2 x = d;
  for (int i = 0; i < 10; ++i) {
    float r2 = dot(x, x);
    float radial = 1.0 + uDistortion.x * r2 + uDistortion.y * r2 * r2;
    float dradial = 2.0 * (uDistortion.x + 2.0 * uDistortion.y * r2);  // d radial / d(x) = dradial * x
    float p1 = uDistortion.z, p2 = uDistortion.w;
    mat2 jacobian = mat2(radial + x.x * x.x * dradial + 2.0 * p1 * x.y + 6.0 * p2 * x.x,  // d fx/dx
                         x.y * x.x * dradial + 2.0 * p2 * x.y + 2.0 * p1 * x.x,           // d fy/dx
                         x.x * x.y * dradial + 2.0 * p1 * x.x + 2.0 * p2 * x.y,           // d fx/dy
                         radial + x.y * x.y * dradial + 2.0 * p2 * x.x + 6.0 * p1 * x.y); // d fy/dy
    x -= inverse(jacobian) * (Distort(x) - d);
  }
  return x;
}

vec3 PixelRay(vec2 pixel) {
  vec2 n = Undistort((pixel - uPrincipal) / uFocal);
  return normalize(transpose(uWorldToCamera) * vec3(n, 1.0));
}

vec3 CameraCenter() { return uCameraCenter; }
)";

void SetStudioCamera(const ShaderProgram& program, const View& view, double near, double far) {
  view.camera.Check();
  SetProjectionUniforms(program, view, DepthRange{near, far});
  program.Set("uCameraCenter", Eigen::Vector3f(view.pose.Center().cast<float>()));
  program.Set("uHasDistortion", view.camera.HasDistortion() ? 1 : 0);
}

}  // namespace voltree
