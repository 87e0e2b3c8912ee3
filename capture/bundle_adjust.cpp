#include "capture/bundle_adjust.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <thread>
#include <vector>

#include "core/camera_projection.h"
#include "core/error.h"

namespace voltree {
namespace {

constexpr int kMaxParams = 8;  // OPENCV's; smaller models leave the rest of the block unused
using IntrinsicsBlock = std::array<double, kMaxParams>;

// One observation: the pixel where `point` appears in a photo with pose (quaternion w x y z,
// translation) and intrinsics in COLMAP's order.
struct ReprojectionResidual {
  CameraModel model;
  Eigen::Vector2d observed;

  template <typename T>
  bool operator()(const T* rotation, const T* translation, const T* point, const T* intrinsics, T* residual) const {
    T camera[3];
    ceres::QuaternionRotatePoint(rotation, point, camera);
    for (int i = 0; i < 3; ++i) camera[i] += translation[i];
    if (!(camera[2] > T(1e-9))) return false;  // behind the photo: no valid projection
    const Eigen::Matrix<T, 2, 1> pixel =
        ProjectToPixel(model, intrinsics, Eigen::Matrix<T, 3, 1>(camera[0], camera[1], camera[2]));
    residual[0] = pixel.x() - T(observed.x());
    residual[1] = pixel.y() - T(observed.y());
    return true;
  }
};

// The parameters of a camera that adjustment may move: focal lengths and distortion, not the
// principal point (as COLMAP), nor the padding past the model's own parameters.
std::vector<int> FixedIntrinsics(const Camera& camera) {
  std::vector<int> fixed;
  const int first_principal = HasSingleFocal(camera.model) ? 1 : 2;
  fixed.push_back(first_principal);
  fixed.push_back(first_principal + 1);
  for (int i = int(camera.params.size()); i < kMaxParams; ++i) fixed.push_back(i);
  return fixed;
}

double PixelError(const Camera& camera, const Pose& pose, const Eigen::Vector3d& point, const Eigen::Vector2d& seen) {
  const Eigen::Vector3d in_camera = pose.ToCamera(point);
  if (!(in_camera.z() > 0)) return std::numeric_limits<double>::infinity();
  return (camera.Project(in_camera) - seen).norm();
}

// Drops the observations further than `max_error` from their point and the points left with fewer
// than two; every point's error becomes the mean over what it keeps.
void DropFarObservations(ColmapModel& model, double max_error) {
  for (auto it = model.points.begin(); it != model.points.end();) {
    ColmapPoint& point = it->second;
    std::vector<std::pair<int, int>> kept;
    double error_sum = 0;
    for (const auto& [image_id, index] : point.track) {
      ColmapImage& image = model.images.at(image_id);
      const double error =
          PixelError(model.cameras.at(image.camera_id), image.pose, point.position, image.keypoints.at(index));
      if (error <= max_error) {
        kept.push_back({image_id, index});
        error_sum += error;
      } else {
        image.point3d_ids.at(index) = -1;
      }
    }
    if (kept.size() < 2) {
      for (const auto& [image_id, index] : kept) model.images.at(image_id).point3d_ids.at(index) = -1;
      it = model.points.erase(it);
      continue;
    }
    point.track = std::move(kept);
    point.error = error_sum / double(point.track.size());
    ++it;
  }
}

}  // namespace

void RobustAdjustOptions::Check() const {
  if (!(loss_scale >= 0 && std::isfinite(loss_scale)))
    FailOption("RobustAdjustOptions.loss_scale", "must be >= 0 pixels (0: no adjustment), got ", loss_scale);
  if (!(max_error > 0 && std::isfinite(max_error)))
    FailOption("RobustAdjustOptions.max_error", "must be a positive number of pixels, got ", max_error);
  if (max_iterations < 1) FailOption("RobustAdjustOptions.max_iterations", "must be at least 1, got ", max_iterations);
  if (threads < 0) FailOption("RobustAdjustOptions.threads", "must be >= 0 (0: every hardware thread), got ", threads);
}

RobustAdjustReport AdjustBundleRobustly(ColmapModel& model, const RobustAdjustOptions& options) {
  options.Check();
  const auto start = std::chrono::steady_clock::now();
  RobustAdjustReport report;
  report.error_before = report.error_after = MeanReprojectionError(model);
  report.observations_before = report.observations_after = ObservationCount(model);
  report.points_before = report.points_after = model.points.size();
  if (options.loss_scale == 0) {
    report.note = "turned off";
    return report;
  }
  if (model.images.size() < 2 || model.points.empty()) {
    report.note = "fewer than two photos or no points";
    return report;
  }

  // Parameter blocks, kept apart from the model until the solve succeeds.
  std::map<int, std::array<double, 4>> rotations;  // w x y z, Ceres' order
  std::map<int, Eigen::Vector3d> translations;
  std::map<int64_t, Eigen::Vector3d> points;
  std::map<int, IntrinsicsBlock> intrinsics;
  for (const auto& [id, camera] : model.cameras) {
    IntrinsicsBlock block{};
    std::copy(camera.params.begin(), camera.params.end(), block.begin());
    intrinsics[id] = block;
  }
  for (const auto& [id, image] : model.images) {
    const Eigen::Quaterniond& q = image.pose.rotation;
    rotations[id] = {q.w(), q.x(), q.y(), q.z()};
    translations[id] = image.pose.translation;
  }
  for (const auto& [id, point] : model.points) points[id] = point.position;

  ceres::Problem problem;
  ceres::LossFunction* loss = new ceres::CauchyLoss(options.loss_scale);  // shared; the problem deletes it once
  for (const auto& [id, point] : model.points)
    for (const auto& [image_id, index] : point.track) {
      const ColmapImage& image = model.images.at(image_id);
      const Camera& camera = model.cameras.at(image.camera_id);
      auto* cost = new ceres::AutoDiffCostFunction<ReprojectionResidual, 2, 4, 3, 3, kMaxParams>(
          new ReprojectionResidual{camera.model, image.keypoints.at(index)});
      problem.AddResidualBlock(cost, loss, rotations[image_id].data(), translations[image_id].data(), points[id].data(),
                               intrinsics[image.camera_id].data());
    }

  for (auto& [id, rotation] : rotations)
    if (problem.HasParameterBlock(rotation.data())) problem.SetManifold(rotation.data(), new ceres::QuaternionManifold);
  for (auto& [id, block] : intrinsics) {
    if (!problem.HasParameterBlock(block.data())) continue;
    if (options.keep_intrinsics)
      problem.SetParameterBlockConstant(block.data());
    else
      problem.SetManifold(block.data(), new ceres::SubsetManifold(kMaxParams, FixedIntrinsics(model.cameras.at(id))));
  }
  // The gauge: the first photo's pose, and the scale through the largest coordinate of the
  // second photo's translation (as COLMAP's own adjustment does).
  const int first = model.images.begin()->first, second = std::next(model.images.begin())->first;
  if (problem.HasParameterBlock(rotations[first].data())) {
    problem.SetParameterBlockConstant(rotations[first].data());
    problem.SetParameterBlockConstant(translations[first].data());
  }
  if (problem.HasParameterBlock(translations[second].data())) {
    int largest = 0;
    translations[second].cwiseAbs().maxCoeff(&largest);
    problem.SetManifold(translations[second].data(), new ceres::SubsetManifold(3, {largest}));
  }

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_SCHUR;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  report.iterations = int(summary.iterations.size());

  bool finite = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
  for (const auto& [id, t] : translations) finite = finite && t.allFinite();
  for (const auto& [id, p] : points) finite = finite && p.allFinite();
  if (!finite) {
    report.note = Str("the solver gave no usable result (", summary.message, ")");
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

  for (auto& [id, image] : model.images) {
    const auto& q = rotations.at(id);
    image.pose.rotation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    image.pose.translation = translations.at(id);
  }
  for (auto& [id, point] : model.points) point.position = points.at(id);
  for (auto& [id, camera] : model.cameras)
    std::copy_n(intrinsics.at(id).begin(), camera.params.size(), camera.params.begin());
  DropFarObservations(model, options.max_error);

  report.adjusted = true;
  report.error_after = MeanReprojectionError(model);
  report.observations_after = ObservationCount(model);
  report.points_after = model.points.size();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace voltree
