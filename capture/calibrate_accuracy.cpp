#include "capture/calibrate_accuracy.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"

namespace voltree {

CameraAccuracy CompareCameras(const std::vector<View>& estimated, const std::vector<View>& truth) {
  std::map<std::string, const View*> by_name;
  for (const View& view : estimated) by_name[view.name] = &view;
  CameraAccuracy accuracy;
  std::vector<const View*> pairs_estimated, pairs_true;
  for (const View& view : truth) {
    const auto found = by_name.find(view.name);
    if (found == by_name.end()) {
      accuracy.missing.push_back(view.name);
      continue;
    }
    pairs_estimated.push_back(found->second);
    pairs_true.push_back(&view);
  }
  accuracy.matched = int(pairs_true.size());
  if (accuracy.matched < 3) Fail("camera comparison needs 3 views in both models, found ", accuracy.matched);

  Eigen::Matrix3Xd from(3, accuracy.matched), to(3, accuracy.matched);
  for (int i = 0; i < accuracy.matched; ++i) {
    from.col(i) = pairs_estimated[i]->pose.Center();
    to.col(i) = pairs_true[i]->pose.Center();
  }
  const Eigen::Matrix4d transform = Eigen::umeyama(from, to, true);
  const Eigen::Matrix3d scaled_rotation = transform.topLeftCorner<3, 3>();
  const double scale = std::cbrt(scaled_rotation.determinant());
  if (!(scale > 0) || !std::isfinite(scale))
    Fail("camera comparison: the estimated centres are degenerate (all in one point or on a line)");
  Similarity& align = accuracy.estimated_to_true;
  align.scale = scale;
  align.rotation = Eigen::Quaterniond(Eigen::Matrix3d(scaled_rotation / scale)).normalized();
  align.translation = transform.topRightCorner<3, 1>();

  const Eigen::Vector3d centroid = to.rowwise().mean();
  double distance = 0;
  for (int i = 0; i < accuracy.matched; ++i) distance += (to.col(i) - centroid).norm();
  distance /= accuracy.matched;
  if (!(distance > 0)) Fail("camera comparison: the true cameras are all in one place");

  for (int i = 0; i < accuracy.matched; ++i) {
    const Pose aligned = TransformPose(pairs_estimated[i]->pose, align);
    const double angle = aligned.rotation.angularDistance(pairs_true[i]->pose.rotation) * 180.0 / M_PI;
    const double center = (align.Apply(from.col(i)) - to.col(i)).norm() / distance;
    accuracy.views.push_back({pairs_true[i]->name, angle, center});
    accuracy.mean_rotation_degrees += angle / accuracy.matched;
    accuracy.max_rotation_degrees = std::max(accuracy.max_rotation_degrees, angle);
    accuracy.mean_center_error += center / accuracy.matched;
    accuracy.max_center_error = std::max(accuracy.max_center_error, center);
  }
  return accuracy;
}

}  // namespace voltree
