#include "samples/studio_projection.h"

#include "core/error.h"

namespace voltree {

const char* const kStudioProjectionGlsl = R"(
uniform mat3 uWorldToCamera;
uniform vec3 uTranslation;
uniform vec3 uCameraCenter;
uniform vec2 uFocal;
uniform vec2 uPrincipal;
uniform vec4 uDistortion;  // k1 k2 p1 p2; zeros where the model has none (one formula for all)
uniform int uHasDistortion;
uniform vec2 uImageSize;   // output pixels, before supersampling
uniform vec2 uDepthRange;  // near, far in camera z

// COLMAP's OPENCV distortion; SIMPLE_RADIAL and RADIAL are its special cases.
vec2 Distort(vec2 n) {
  float r2 = dot(n, n);
  float radial = 1.0 + uDistortion.x * r2 + uDistortion.y * r2 * r2;
  float uv = n.x * n.y;
  return vec2(n.x * radial + 2.0 * uDistortion.z * uv + uDistortion.w * (r2 + 2.0 * n.x * n.x),
              n.y * radial + 2.0 * uDistortion.w * uv + uDistortion.z * (r2 + 2.0 * n.y * n.y));
}

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

vec4 ProjectToClip(vec3 world) {
  vec3 c = uWorldToCamera * world + uTranslation;
  float z = c.z;
  vec2 pixel = uFocal * Distort(c.xy / max(z, 1e-6)) + uPrincipal;
  // Pixel y grows down, NDC y up; window coordinate = pixel coordinate (COLMAP: centre of pixel
  // (0,0) at (0.5, 0.5), which is where GL samples pixel (0,0) too).
  vec2 ndc = vec2(2.0 * pixel.x / uImageSize.x - 1.0, 1.0 - 2.0 * pixel.y / uImageSize.y);
  float n = uDepthRange.x, f = uDepthRange.y;
  // Multiplying by w = z keeps texture interpolation perspective-correct.
  return vec4(ndc * z, ((f + n) * z - 2.0 * f * n) / (f - n), z);
}

vec3 PixelRay(vec2 pixel) {
  vec2 n = Undistort((pixel - uPrincipal) / uFocal);
  return normalize(transpose(uWorldToCamera) * vec3(n, 1.0));
}

vec3 CameraCenter() { return uCameraCenter; }
)";

void SetStudioCamera(const ShaderProgram& program, const View& view, double near, double far) {
  const Camera& camera = view.camera;
  camera.Check();
  if (!(near > 0 && far > near)) Fail("studio: bad depth range [", near, ", ", far, "]");
  Eigen::Vector4f distortion = Eigen::Vector4f::Zero();
  const std::vector<double>& p = camera.params;
  switch (camera.model) {
    case CameraModel::kSimplePinhole:
    case CameraModel::kPinhole: break;
    case CameraModel::kSimpleRadial: distortion[0] = static_cast<float>(p[3]); break;
    case CameraModel::kRadial: distortion << float(p[3]), float(p[4]), 0, 0; break;
    case CameraModel::kOpenCV: distortion << float(p[4]), float(p[5]), float(p[6]), float(p[7]); break;
  }
  program.Set("uWorldToCamera", Eigen::Matrix3f(view.pose.rotation.toRotationMatrix().cast<float>()));
  program.Set("uTranslation", Eigen::Vector3f(view.pose.translation.cast<float>()));
  program.Set("uCameraCenter", Eigen::Vector3f(view.pose.Center().cast<float>()));
  program.Set("uFocal", Eigen::Vector2f(float(camera.FocalX()), float(camera.FocalY())));
  program.Set("uPrincipal", Eigen::Vector2f(camera.PrincipalPoint().cast<float>()));
  program.Set("uDistortion", distortion);
  program.Set("uHasDistortion", camera.HasDistortion() ? 1 : 0);
  program.Set("uImageSize", Eigen::Vector2f(float(camera.width), float(camera.height)));
  program.Set("uDepthRange", Eigen::Vector2f(float(near), float(far)));
}

}  // namespace voltree
