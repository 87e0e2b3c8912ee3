#include "render/view_selection.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace voltree {
namespace {

double Angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));  // accurate near 0, unlike acos
}

}  // namespace

ViewPair SelectViews(const std::vector<VtreeView>& views, const Eigen::Vector3d& centre, const Eigen::Vector3d& eye) {
  if (views.empty()) Fail("render: the asset has no input views");
  const Eigen::Vector3d look = centre - eye;
  double best = std::numeric_limits<double>::infinity(), second = best;
  ViewPair pair;
  for (int v = 0; v < int(views.size()); ++v) {
    const double angle = Angle(look, centre - views[v].position);
    if (angle < best) {
      second = best;
      pair.second = pair.first;
      best = angle;
      pair.first = v;
    } else if (angle < second) {
      second = angle;
      pair.second = v;
    }
  }
  if (views.size() == 1 || best + second <= 0) {
    if (views.size() == 1) pair.second = pair.first;
    pair.first_weight = 1;
    pair.second_weight = 0;
    return pair;
  }
  pair.first_weight = float(second / (best + second));
  pair.second_weight = 1 - pair.first_weight;
  return pair;
}

}  // namespace voltree
