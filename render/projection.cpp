#include "render/projection.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

void DepthRange::Check() const {
  if (!(near > 0 && far > near)) Fail("render: bad depth range [", near, ", ", far, "]");
}

DepthRange DepthRangeForSphere(const Eigen::Vector3d& eye, const Eigen::Vector3d& centre, double radius) {
  const double distance = (eye - centre).norm();
  const double near = std::max(distance - radius, 1e-4 * radius);
  return {near, distance + radius * 1.01 + near};
}

const char* const kProjectionGlsl = R"(
uniform mat3 uWorldToCamera;
uniform vec3 uTranslation;
uniform vec2 uFocal;
uniform vec2 uPrincipal;
uniform vec4 uDistortion;  // k1 k2 p1 p2 (COLMAP OPENCV; zeros for PINHOLE)
uniform vec2 uImageSize;
uniform vec2 uDepthRange;

vec2 Distort(vec2 n) {
  float r2 = dot(n, n);
  float radial = 1.0 + uDistortion.x * r2 + uDistortion.y * r2 * r2;
  float uv = n.x * n.y;
  return vec2(n.x * radial + 2.0 * uDistortion.z * uv + uDistortion.w * (r2 + 2.0 * n.x * n.x),
              n.y * radial + 2.0 * uDistortion.w * uv + uDistortion.z * (r2 + 2.0 * n.y * n.y));
}

vec4 ProjectToClip(vec3 world) {
  vec3 c = uWorldToCamera * world + uTranslation;
  float z = c.z;
  // Pixel coordinates times z: exact and linear in c for a pinhole.
  vec2 xy = any(notEqual(uDistortion, vec4(0.0))) ? Distort(c.xy / max(z, 1e-6)) * z : c.xy;
  vec2 pixel_z = uFocal * xy + uPrincipal * z;
  vec2 ndc_z = vec2(2.0 * pixel_z.x / uImageSize.x - z, z - 2.0 * pixel_z.y / uImageSize.y);
  float n = uDepthRange.x, f = uDepthRange.y;
  return vec4(ndc_z, ((f + n) * z - 2.0 * f * n) / (f - n), z);
}
)";

void SetProjectionUniforms(const ShaderProgram& program, const View& view, const DepthRange& depth) {
  depth.Check();
  const Camera& intrinsics = view.camera;
  Eigen::Vector4f distortion = Eigen::Vector4f::Zero();
  const std::vector<double>& p = intrinsics.params;
  switch (intrinsics.model) {
    case CameraModel::kSimplePinhole:
    case CameraModel::kPinhole:
      break;
    case CameraModel::kSimpleRadial:
      distortion[0] = float(p[3]);
      break;
    case CameraModel::kRadial:
      distortion << float(p[3]), float(p[4]), 0, 0;
      break;
    case CameraModel::kOpenCV:
      distortion << float(p[4]), float(p[5]), float(p[6]), float(p[7]);
      break;
  }
  program.Set("uWorldToCamera", Eigen::Matrix3f(view.pose.rotation.toRotationMatrix().cast<float>()));
  program.Set("uTranslation", Eigen::Vector3f(view.pose.translation.cast<float>()));
  program.Set("uFocal", Eigen::Vector2f(float(intrinsics.FocalX()), float(intrinsics.FocalY())));
  program.Set("uPrincipal", Eigen::Vector2f(intrinsics.PrincipalPoint().cast<float>()));
  program.Set("uDistortion", distortion);
  program.Set("uImageSize", Eigen::Vector2f(float(intrinsics.width), float(intrinsics.height)));
  program.Set("uDepthRange", Eigen::Vector2f(float(depth.near), float(depth.far)));
}

}  // namespace voltree
