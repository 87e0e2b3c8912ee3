// Camera intrinsics and poses with COLMAP's conventions:
//   x_cam = R * x_world + t, camera X right, Y down, Z forward;
//   pixel (0,0) covers [0,1)x[0,1), so its center is at (0.5, 0.5).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

namespace voltree {

enum class CameraModel { kSimplePinhole, kPinhole, kSimpleRadial, kRadial, kOpenCV };

// COLMAP's name ("PINHOLE") and number of parameters for each model.
std::string_view CameraModelName(CameraModel model);
int CameraModelParamCount(CameraModel model);
// Throws Error listing the supported names when `name` is unknown.
CameraModel CameraModelFromName(std::string_view name);

struct Camera {
  CameraModel model = CameraModel::kPinhole;
  int width = 0;
  int height = 0;
  // In COLMAP's order, e.g. PINHOLE: fx fy cx cy; OPENCV: fx fy cx cy k1 k2 p1 p2.
  std::vector<double> params;

  // Throws Error when the parameter count, focal length or image size is invalid.
  void Check() const;

  double FocalX() const;
  double FocalY() const;
  Eigen::Vector2d PrincipalPoint() const;
  bool HasDistortion() const;

  // Camera-space point (z > 0) -> pixel coordinates, distortion applied.
  Eigen::Vector2d Project(const Eigen::Vector3d& point_camera) const;
  // Pixel coordinates -> camera-space direction with z = 1, distortion removed.
  Eigen::Vector3d Unproject(const Eigen::Vector2d& pixel) const;

  // Normalized image coordinates (x/z, y/z) -> distorted normalized coordinates, and back.
  Eigen::Vector2d Distort(const Eigen::Vector2d& normalized) const;
  Eigen::Vector2d Undistort(const Eigen::Vector2d& distorted) const;

  static Camera Pinhole(int width, int height, double focal_x, double focal_y, double cx, double cy);
  // The same lens with the image resampled to width x height: focal lengths and principal point
  // scale with the image, distortion (in normalized coordinates) does not.
  Camera Resized(int new_width, int new_height) const;
};

// World-to-camera rigid transform.
struct Pose {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d ToCamera(const Eigen::Vector3d& world) const { return rotation * world + translation; }
  Eigen::Vector3d ToWorld(const Eigen::Vector3d& camera) const { return rotation.conjugate() * (camera - translation); }
  // Camera center in world coordinates: -R^T t.
  Eigen::Vector3d Center() const { return -(rotation.conjugate() * translation); }
  // Unit viewing direction (camera +Z) in world coordinates.
  Eigen::Vector3d ViewDirection() const { return rotation.conjugate() * Eigen::Vector3d::UnitZ(); }

  // A camera at `eye` looking at `target`; `up` is the world direction that appears up in the image.
  static Pose LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up);
};

// One calibrated photo: what reconstruction and rendering need about a view.
struct View {
  std::string name;  // image file name relative to images/
  Camera camera;
  Pose pose;

  // World point -> pixel; returns false when the point is behind the camera.
  bool WorldToPixel(const Eigen::Vector3d& world, Eigen::Vector2d* pixel) const;
  // Unit world-space direction of the ray through a pixel position (e.g. (x+0.5, y+0.5)).
  Eigen::Vector3d PixelRay(const Eigen::Vector2d& pixel) const;
};

}  // namespace voltree
