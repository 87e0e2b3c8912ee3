// Scene normalization: similarity transforms, up from the cameras, the visual hull.
#include "capture/normalize.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "capture/calibrate_accuracy.h"
#include "capture/normalize_hull.h"
#include "core/error.h"
#include "capture/box_matte.h"

namespace voltree {
namespace {

using test::BoxMatte;

// 12 cameras on an orbit of radius 4 at height 1.5 around a tree 1 high, in a Z-up world.
std::vector<View> Orbit(int count = 12, double jitter_height = 0, double low_ring = 1.5) {
  std::vector<View> views;
  for (int i = 0; i < count; ++i) {
    const double angle = 2 * M_PI * i / count;
    const double height = i % 2 ? low_ring : 1.5;
    const Eigen::Vector3d eye(4 * std::cos(angle), 4 * std::sin(angle), height + jitter_height * ((i % 3) - 1));
    views.push_back({"view_" + std::to_string(100 + i) + ".png", Camera::Pinhole(160, 120, 150, 150, 80, 60),
                     Pose::LookAt(eye, {0, 0, 0.5}, {0, 0, 1})});
  }
  return views;
}

Similarity SomeSimilarity() {
  Similarity s;
  s.scale = 0.37;
  s.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.8, 0.5).normalized()));
  s.translation = {2, -5, 0.7};
  return s;
}

TEST(Normalize, TransformKeepsWhatCamerasSee) {
  const Similarity s = SomeSimilarity();
  const Eigen::Vector3d point(0.1, -0.2, 0.8);
  for (const View& view : Orbit()) {
    View moved = view;
    moved.pose = TransformPose(view.pose, s);
    Eigen::Vector2d before, after;
    ASSERT_TRUE(view.WorldToPixel(point, &before));
    ASSERT_TRUE(moved.WorldToPixel(s.Apply(point), &after));
    EXPECT_LT((before - after).norm(), 1e-9);
    EXPECT_LT((moved.pose.Center() - s.Apply(view.pose.Center())).norm(), 1e-9);
  }
  // Composition.
  const Similarity twice = s.After(s);
  EXPECT_LT((twice.Apply(point) - s.Apply(s.Apply(point))).norm(), 1e-12);
}

TEST(Normalize, UpFromAnOrbitUnderAnyRotation) {
  const Similarity s = SomeSimilarity();
  for (double jitter : {0.0, 0.2}) {
    std::vector<View> views = Orbit(12, jitter);
    for (View& view : views) view.pose = TransformPose(view.pose, s);
    const Eigen::Vector3d expected = s.rotation * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d up = EstimateUp(views);
    // An orbit of centres in a plane gives the exact normal; 3 rings at +-0.2 still nearly so
    // (the plane fit is exact for a symmetric set: measured 0).
    EXPECT_LT(std::acos(std::min(1.0, up.dot(expected))), 1e-6) << "jitter " << jitter;
    EXPECT_LT((RotationToZUp(up) * up - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  }
  // A line of cameras (a walk past the tree) falls back to the photos' up.
  std::vector<View> line;
  for (int i = 0; i < 5; ++i)
    line.push_back(
        {"a", Camera::Pinhole(10, 10, 10, 10, 5, 5), Pose::LookAt({double(i), -4, 1}, {double(i), 0, 1}, {0, 0, 1})});
  EXPECT_LT((EstimateUp(line) - Eigen::Vector3d::UnitZ()).norm(), 1e-9);
  EXPECT_THROW(EstimateUp({}), Error);
}

TEST(Normalize, LookAtPointIsWhereTheOrbitLooks) {
  EXPECT_LT((LookAtPoint(Orbit()) - Eigen::Vector3d(0, 0, 0.5)).norm(), 1e-9);
}

// Two rings: cameras that all look down steeply cannot carve below the base (the region under the
// box hides behind it), so the hull would reach under the trunk; a low ring fixes that.
TEST(VisualHull, BoundsAndBaseOfABox) {
  const std::vector<View> views = Orbit(16, 0, 0.3);
  std::vector<Image8> mattes;
  for (const View& view : views) mattes.push_back(BoxMatte(view));
  const VisualHull hull = CarveVisualHullAuto(views, mattes, HullOptions{});
  // The hull contains the box and is conservative by at most the dilation (about 2 voxels) plus
  // what 16 views cannot carve at the corners; measured: 0.086 beyond the box in x and y, 0.07 in z.
  const double slack = 0.1;
  std::printf("hull %s .. %s, base %s\n", Str(hull.bounds_min.transpose()).c_str(),
              Str(hull.bounds_max.transpose()).c_str(), Str(hull.base.transpose()).c_str());
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(hull.bounds_min[k], k < 2 ? -0.2 : 0.0);
    EXPECT_GE(hull.bounds_max[k], k < 2 ? 0.2 : 1.0);
    EXPECT_GT(hull.bounds_min[k], (k < 2 ? -0.2 : 0.0) - slack) << k;
    EXPECT_LT(hull.bounds_max[k], (k < 2 ? 0.2 : 1.0) + slack) << k;
  }
  EXPECT_LT(hull.base.head<2>().norm(), 0.02);
  EXPECT_NEAR(hull.base.z(), 0.0, slack);
  // Mattes that see nothing carve everything.
  std::vector<Image8> empty(views.size(), Image8(160, 120, 1, 0));
  EXPECT_THROW(CarveVisualHullAuto(views, empty, HullOptions{}), Error);
}

TEST(CalibrateAccuracy, ExactUpToSimilarityAndSensitiveToErrors) {
  const std::vector<View> truth = Orbit();
  std::vector<View> estimated = truth;
  const Similarity s = SomeSimilarity();
  for (View& view : estimated) view.pose = TransformPose(view.pose, s);
  CameraAccuracy accuracy = CompareCameras(estimated, truth);
  EXPECT_EQ(accuracy.matched, 12);
  EXPECT_LT(accuracy.max_rotation_degrees, 1e-6);
  EXPECT_LT(accuracy.max_center_error, 1e-9);
  EXPECT_NEAR(accuracy.estimated_to_true.scale, 1 / s.scale, 1e-9);

  // Turn one camera by 1 degree about its optical axis, keeping its centre.
  Pose& turned = estimated[3].pose;
  const Eigen::Vector3d center = turned.Center();
  turned.rotation = Eigen::AngleAxisd(M_PI / 180, Eigen::Vector3d::UnitZ()) * turned.rotation;
  turned.translation = -(turned.rotation * center);
  // Move another by 1% of the distance to the centroid (4.0 here), keeping its rotation.
  Pose& moved = estimated[5].pose;
  const Eigen::Vector3d shifted = moved.Center() + s.rotation * (s.scale * 0.04 * Eigen::Vector3d(0.6, 0.8, 0));
  moved.translation = -(moved.rotation * shifted);
  accuracy = CompareCameras(estimated, truth);
  // The least-squares alignment spreads the moved centre over all: measured max 1.00 degree and
  // a centre error a little under 1%.
  std::printf("perturbed: max rotation %.4f deg, max centre error %.5f\n", accuracy.max_rotation_degrees,
              accuracy.max_center_error);
  EXPECT_NEAR(accuracy.max_rotation_degrees, 1.0, 0.05);
  EXPECT_GT(accuracy.max_center_error, 0.007);
  EXPECT_LT(accuracy.max_center_error, 0.011);

  estimated.resize(2);
  EXPECT_THROW(CompareCameras(estimated, truth), Error);
}

// Ground at z = 0.3 (noisy) under a crown of points and a few stray points below: the slab of
// ground points wins; far-away ground and too few points do not count.
TEST(Normalize, GroundHeightIsTheDensestSlabUnderTheTree) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 200; ++i) points.emplace_back(3 * unit(random), 3 * unit(random), 0.3 + 0.005 * unit(random));
  for (int i = 0; i < 150; ++i) points.emplace_back(unit(random), unit(random), 2 + 1.5 * unit(random));  // crown
  for (int i = 0; i < 10; ++i) points.emplace_back(unit(random), unit(random), -0.2 + 0.005 * unit(random));
  for (int i = 0; i < 300; ++i) points.emplace_back(20 + unit(random), 0, 1.0);  // far away: outside the radius
  const std::optional<double> ground = EstimateGroundHeight(points, {0, 0}, 4, -0.5, 1.0, 0.04);
  ASSERT_TRUE(ground.has_value());
  EXPECT_NEAR(*ground, 0.3, 0.006);
  EXPECT_FALSE(EstimateGroundHeight(points, {0, 0}, 4, -0.5, 0.2, 0.04).has_value());  // 10 stray points only
}

}  // namespace
}  // namespace voltree
