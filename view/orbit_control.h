// The viewer's camera: an orbit about a centre (azimuth, elevation, distance) that the mouse turns,
// pans and zooms and WASD flies, starting where `voltree render --orbit` starts.
#pragma once

#include <Eigen/Core>

#include "core/camera.h"

namespace voltree {

struct OrbitState {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1;  // of what is looked at: sets the field of view, as OrbitCamerasAround does
  double distance = 3;
  double azimuth_degrees = 0, elevation_degrees = 20;
};

class OrbitControl {
 public:
  explicit OrbitControl(const OrbitState& home) : home_(home), state_(home) {}

  const OrbitState& state() const { return state_; }
  // A PINHOLE camera of the given size (render/orbit.h's OrbitCamerasAround for this state).
  View Camera(int width, int height) const;

  void Turn(double dx_pixels, double dy_pixels);  // drag: 0.4 degree per pixel
  void Pan(double dx_pixels, double dy_pixels);   // the centre moves in the image plane
  void Zoom(double wheel_steps);                  // distance x 0.9 per step
  void Fly(double forward, double right);         // in units of the radius, along the view
  void Reset() { state_ = home_; }

 private:
  OrbitState home_, state_;
};

}  // namespace voltree
