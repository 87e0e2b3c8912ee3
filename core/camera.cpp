#include "core/camera.h"

#include <array>
#include <cmath>

#include "core/camera_projection.h"
#include "core/error.h"

namespace voltree {
namespace {

struct ModelInfo {
  CameraModel model;
  std::string_view name;
  int param_count;
};

constexpr std::array<ModelInfo, 5> kModels = {{
    {CameraModel::kSimplePinhole, "SIMPLE_PINHOLE", 3},
    {CameraModel::kPinhole, "PINHOLE", 4},
    {CameraModel::kSimpleRadial, "SIMPLE_RADIAL", 4},
    {CameraModel::kRadial, "RADIAL", 5},
    {CameraModel::kOpenCV, "OPENCV", 8},
}};

const ModelInfo& Info(CameraModel model) {
  for (const ModelInfo& info : kModels)
    if (info.model == model) return info;
  Fail("unknown camera model enum value ", static_cast<int>(model));
}

}  // namespace

std::string_view CameraModelName(CameraModel model) { return Info(model).name; }
int CameraModelParamCount(CameraModel model) { return Info(model).param_count; }

CameraModel CameraModelFromName(std::string_view name) {
  for (const ModelInfo& info : kModels)
    if (info.name == name) return info.model;
  Fail("unknown camera model '", name, "' (expected SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL or OPENCV)");
}

void Camera::Check() const {
  if (width <= 0 || height <= 0) Fail("camera size ", width, "x", height, " is not positive");
  if (static_cast<int>(params.size()) != CameraModelParamCount(model))
    Fail("camera model ", CameraModelName(model), " needs ", CameraModelParamCount(model), " parameters, got ",
         params.size());
  for (size_t i = 0; i < params.size(); ++i)
    if (!std::isfinite(params[i]))
      Fail("camera ", CameraModelName(model), " parameter ", i + 1, " of ", params.size(), " is ", params[i],
           "; expected a finite number");
  if (!(FocalX() > 0) || !(FocalY() > 0))
    Fail("camera focal length must be positive, got ", FocalX(), " and ", FocalY());
}

double Camera::FocalX() const { return params.at(0); }
double Camera::FocalY() const { return HasSingleFocal(model) ? params.at(0) : params.at(1); }

Eigen::Vector2d Camera::PrincipalPoint() const {
  return HasSingleFocal(model) ? Eigen::Vector2d(params.at(1), params.at(2))
                               : Eigen::Vector2d(params.at(2), params.at(3));
}

bool Camera::HasDistortion() const {
  const int first = HasSingleFocal(model) ? 3 : 4;
  for (size_t i = first; i < params.size(); ++i)
    if (params[i] != 0.0) return true;
  return false;
}

Eigen::Vector2d Camera::Distort(const Eigen::Vector2d& n) const { return DistortNormalized(model, params.data(), n); }

Eigen::Vector2d Camera::Undistort(const Eigen::Vector2d& distorted) const {
  if (!HasDistortion()) return distorted;
  // Newton's method with a numerical Jacobian, as COLMAP does; converges in a few steps for
  // realistic lenses.
  Eigen::Vector2d x = distorted;
  constexpr double kStep = 1e-8;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Eigen::Vector2d residual = Distort(x) - distorted;
    if (residual.squaredNorm() < 1e-24) break;
    Eigen::Matrix2d jacobian;
    jacobian.col(0) = (Distort(x + Eigen::Vector2d(kStep, 0)) - Distort(x)) / kStep;
    jacobian.col(1) = (Distort(x + Eigen::Vector2d(0, kStep)) - Distort(x)) / kStep;
    x -= jacobian.inverse() * residual;
  }
  return x;
}

Eigen::Vector2d Camera::Project(const Eigen::Vector3d& p) const { return ProjectToPixel(model, params.data(), p); }

Eigen::Vector3d Camera::Unproject(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d c = PrincipalPoint();
  const Eigen::Vector2d distorted((pixel.x() - c.x()) / FocalX(), (pixel.y() - c.y()) / FocalY());
  const Eigen::Vector2d n = Undistort(distorted);
  return {n.x(), n.y(), 1.0};
}

Camera Camera::Resized(int new_width, int new_height) const {
  Camera out = *this;
  out.width = new_width, out.height = new_height;
  const double sx = double(new_width) / width, sy = double(new_height) / height;
  auto& p = out.params;
  switch (model) {
    case CameraModel::kPinhole:
    case CameraModel::kOpenCV:
      p[0] *= sx, p[1] *= sy, p[2] *= sx, p[3] *= sy;
      break;
    default:
      p[0] *= 0.5 * (sx + sy), p[1] *= sx, p[2] *= sy;
      break;  // one focal length, then cx, cy
  }
  return out;
}

Camera Camera::Pinhole(int width, int height, double focal_x, double focal_y, double cx, double cy) {
  return Camera{CameraModel::kPinhole, width, height, {focal_x, focal_y, cx, cy}};
}

Pose Pose::LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = (target - eye).normalized();   // camera +Z
  const Eigen::Vector3d right = forward.cross(up).normalized();  // camera +X
  const Eigen::Vector3d down = forward.cross(right);             // camera +Y
  Eigen::Matrix3d world_to_camera;
  world_to_camera.row(0) = right;
  world_to_camera.row(1) = down;
  world_to_camera.row(2) = forward;
  Pose pose;
  pose.rotation = Eigen::Quaterniond(world_to_camera).normalized();
  pose.translation = -(world_to_camera * eye);
  return pose;
}

bool View::WorldToPixel(const Eigen::Vector3d& world, Eigen::Vector2d* pixel) const {
  const Eigen::Vector3d p = pose.ToCamera(world);
  if (p.z() <= 0) return false;
  *pixel = camera.Project(p);
  return true;
}

Eigen::Vector3d View::PixelRay(const Eigen::Vector2d& pixel) const {
  return (pose.rotation.conjugate() * camera.Unproject(pixel)).normalized();
}

}  // namespace voltree
