#include "capture/normalize.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace voltree {

Similarity Similarity::After(const Similarity& first) const {
  Similarity combined;
  combined.scale = scale * first.scale;
  combined.rotation = rotation * first.rotation;
  combined.translation = scale * (rotation * first.translation) + translation;
  return combined;
}

// With x' = s R x + t, a camera x_cam = Rc x + tc sees x' as s x_cam = Rc R^T x' + (s tc - Rc R^T t):
// the new pose keeps the image the same and scales camera-space depth by s.
Pose TransformPose(const Pose& pose, const Similarity& similarity) {
  Pose moved;
  moved.rotation = (pose.rotation * similarity.rotation.conjugate()).normalized();
  moved.translation = similarity.scale * pose.translation - moved.rotation * similarity.translation;
  return moved;
}

ColmapModel TransformModel(const ColmapModel& model, const Similarity& similarity) {
  ColmapModel moved = model;
  for (auto& [id, image] : moved.images) image.pose = TransformPose(image.pose, similarity);
  for (auto& [id, point] : moved.points) point.position = similarity.Apply(point.position);
  return moved;
}

Eigen::Vector3d EstimateUp(const std::vector<View>& views) {
  if (views.empty()) Fail("cannot find the up direction without cameras");
  Eigen::Vector3d image_up = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_center = Eigen::Vector3d::Zero();
  for (const View& view : views) {
    image_up -= view.pose.rotation.conjugate() * Eigen::Vector3d::UnitY();  // camera -Y in world
    mean_center += view.pose.Center();
  }
  mean_center /= double(views.size());
  if (views.size() >= 3) {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const View& view : views) {
      const Eigen::Vector3d d = view.pose.Center() - mean_center;
      scatter += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);  // ascending eigenvalues
    const Eigen::Vector3d values = solver.eigenvalues();
    Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
    if (normal.dot(image_up) < 0) normal = -normal;
    // Trust the plane when the centres are clearly flatter in one direction (an orbit gives a
    // ratio near 0, a line of cameras has no unique normal) and it agrees with the photos' up
    // within 30 degrees (a plane that is not the ground, e.g. cameras on a wall, does not).
    const bool flat = values(0) < 0.5 * values(1);
    const bool agrees = image_up.norm() > 1e-9 && normal.dot(image_up.normalized()) > std::cos(30.0 * M_PI / 180.0);
    if (flat && agrees) return normal;
  }
  if (image_up.norm() < 1e-9) Fail("cannot find the up direction: the cameras' up axes cancel out; pass --up");
  return image_up.normalized();
}

Eigen::Quaterniond RotationToZUp(const Eigen::Vector3d& up) {
  return Eigen::Quaterniond::FromTwoVectors(up.normalized(), Eigen::Vector3d::UnitZ()).normalized();
}

Eigen::Vector3d LookAtPoint(const std::vector<View>& views) {
  // Minimize the sum of squared distances to the lines c + s d: sum (I - d d^T) (x - c) = 0.
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const View& view : views) {
    const Eigen::Vector3d d = view.pose.ViewDirection();
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - d * d.transpose();
    a += projector;
    b += projector * view.pose.Center();
  }
  Eigen::Vector3d mean_center = Eigen::Vector3d::Zero();
  for (const View& view : views) mean_center += view.pose.Center();
  if (views.empty()) Fail("cannot find where cameras look without cameras");
  mean_center /= double(views.size());
  // Parallel axes make `a` singular; fall back to the centroid of the cameras.
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(a);
  if (lu.rank() < 3) return mean_center;
  return lu.solve(b);
}

std::optional<double> EstimateGroundHeight(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& center,
                                           double radius, double z_low, double z_high, double slab, int min_points) {
  std::vector<double> heights;
  for (const Eigen::Vector3d& point : points)
    if ((point.head<2>() - center).norm() <= radius && point.z() >= z_low && point.z() <= z_high)
      heights.push_back(point.z());
  std::sort(heights.begin(), heights.end());
  // Sliding window over the sorted heights: the most points within `slab`; ties go to the lowest.
  size_t best_first = 0, best_count = 0;
  for (size_t first = 0, last = 0; first < heights.size(); ++first) {
    while (last < heights.size() && heights[last] <= heights[first] + slab) ++last;
    if (last - first > best_count) {
      best_count = last - first;
      best_first = first;
    }
  }
  if (int(best_count) < min_points) return std::nullopt;
  return heights[best_first + best_count / 2];
}

}  // namespace voltree
