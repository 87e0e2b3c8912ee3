#include "samples/depth_range.h"

#include <algorithm>

namespace voltree {

std::pair<double, double> BoxDepthRange(const View& view, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  double nearest = 1e300, farthest = -1e300;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    const double z = view.pose.ToCamera(p).z();
    nearest = std::min(nearest, z);
    farthest = std::max(farthest, z);
  }
  farthest = std::max(farthest, 1e-3) * 1.05 + 1e-3;
  return {std::max(nearest * 0.95, farthest * 1e-4), farthest};
}

}  // namespace voltree
