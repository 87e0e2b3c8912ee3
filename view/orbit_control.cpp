#include "view/orbit_control.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "render/orbit.h"

namespace voltree {

View OrbitControl::Camera(int width, int height) const {
  OrbitOptions options;
  options.frames = 1, options.width = width, options.height = height;
  return OrbitCamerasAround(state_.centre, state_.radius, state_.distance, state_.elevation_degrees,
                            state_.azimuth_degrees, options)
      .front();
}

void OrbitControl::Turn(double dx_pixels, double dy_pixels) {
  state_.azimuth_degrees -= 0.4 * dx_pixels;
  state_.elevation_degrees = std::clamp(state_.elevation_degrees + 0.4 * dy_pixels, -89.0, 89.0);
}

void OrbitControl::Pan(double dx_pixels, double dy_pixels) {
  const View view = Camera(512, 512);
  const Eigen::Matrix3d r = view.pose.rotation.toRotationMatrix();
  const double metres_per_pixel = state_.distance / view.camera.FocalX();
  state_.centre += metres_per_pixel * (-dx_pixels * r.row(0).transpose() - dy_pixels * r.row(1).transpose());
}

void OrbitControl::Zoom(double wheel_steps) {
  state_.distance = std::max(0.05 * state_.radius, state_.distance * std::pow(0.9, wheel_steps));
}

void OrbitControl::Fly(double forward, double right) {
  const View view = Camera(512, 512);
  const Eigen::Matrix3d r = view.pose.rotation.toRotationMatrix();
  Eigen::Vector3d ahead = r.row(2).transpose(), side = r.row(0).transpose();
  ahead.z() = 0, side.z() = 0;  // walk on the ground's plane
  if (ahead.norm() > 1e-9) ahead.normalize();
  if (side.norm() > 1e-9) side.normalize();
  state_.centre += state_.radius * 0.05 * (forward * ahead + right * side);
}

}  // namespace voltree
