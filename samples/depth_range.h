// The depth range in which a camera sees a box: the camera depths of its corners, with slack. The
// studio and the LOD bench draw their meshes with it.
#pragma once

#include <Eigen/Core>
#include <utility>

#include "core/camera.h"

namespace voltree {

std::pair<double, double> BoxDepthRange(const View& view, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

}  // namespace voltree
