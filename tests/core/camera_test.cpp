// Camera models and COLMAP's pose convention.
#include "core/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"

namespace voltree {
namespace {

// One camera of each supported model, with realistic (moderate) distortion.
std::vector<Camera> AllModels() {
  return {
      Camera{CameraModel::kSimplePinhole, 640, 480, {500, 320, 240}},
      Camera{CameraModel::kPinhole, 640, 480, {510, 490, 318.5, 241.25}},
      Camera{CameraModel::kSimpleRadial, 640, 480, {500, 320, 240, -0.12}},
      Camera{CameraModel::kRadial, 640, 480, {500, 320, 240, -0.12, 0.03}},
      Camera{CameraModel::kOpenCV, 640, 480, {505, 495, 321, 239, -0.15, 0.04, 0.001, -0.0007}},
  };
}

TEST(Camera, EveryModelProjectsAndUnprojectsRoundTrip) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);  // within a ~53 degree field of view
  std::uniform_real_distribution<double> depth(0.5, 20.0);
  for (const Camera& camera : AllModels()) {
    SCOPED_TRACE(std::string(CameraModelName(camera.model)));
    ASSERT_NO_THROW(camera.Check());
    for (int i = 0; i < 200; ++i) {
      const double z = depth(random);
      const Eigen::Vector3d point(coordinate(random) * z, coordinate(random) * z, z);
      const Eigen::Vector2d pixel = camera.Project(point);
      const Eigen::Vector3d ray = camera.Unproject(pixel);
      EXPECT_NEAR(ray.z(), 1.0, 0.0);
      EXPECT_NEAR(ray.x(), point.x() / z, 1e-9);
      EXPECT_NEAR(ray.y(), point.y() / z, 1e-9);
      // And the other way: pixel -> ray -> pixel.
      EXPECT_LT((camera.Project(ray * 3.0) - pixel).norm(), 1e-9);
    }
  }
}

TEST(Camera, DistortionMovesPointsOnlyWhenNonZero) {
  for (const Camera& camera : AllModels()) {
    const Eigen::Vector2d n(0.3, -0.2);
    if (camera.HasDistortion())
      EXPECT_GT((camera.Distort(n) - n).norm(), 1e-4) << CameraModelName(camera.model);
    else
      EXPECT_EQ(camera.Distort(n), n) << CameraModelName(camera.model);
  }
}

TEST(Camera, PrincipalPointIsWherTheOpticalAxisLands) {
  for (const Camera& camera : AllModels()) {
    const Eigen::Vector2d pixel = camera.Project(Eigen::Vector3d(0, 0, 4));
    EXPECT_NEAR((pixel - camera.PrincipalPoint()).norm(), 0.0, 1e-12);
  }
}

TEST(Camera, ModelNamesRoundTripAndUnknownNamesFail) {
  for (const Camera& camera : AllModels()) EXPECT_EQ(CameraModelFromName(CameraModelName(camera.model)), camera.model);
  try {
    CameraModelFromName("FISHEYE_42");
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("FISHEYE_42"), std::string::npos);
  }
}

TEST(Camera, CheckRejectsInvalidCameras) {
  EXPECT_THROW((Camera{CameraModel::kPinhole, 640, 480, {500, 500, 320}}).Check(), Error);
  EXPECT_THROW((Camera{CameraModel::kPinhole, 0, 480, {500, 500, 320, 240}}).Check(), Error);
  EXPECT_THROW((Camera{CameraModel::kPinhole, 640, 480, {-500, 500, 320, 240}}).Check(), Error);
  EXPECT_THROW((Camera{CameraModel::kPinhole, 640, 480, {NAN, 500, 320, 240}}).Check(), Error);
}

// Worked by hand: a camera at C = (2, 0, 0) looking at the origin with +Z up.
//   forward (camera +Z) = (-1, 0, 0); right (+X) = forward x up = (0, 1, 0);
//   down (+Y) = forward x right = (0, 0, -1).
//   R has rows right, down, forward; t = -R C = (0, 0, 2).
TEST(Pose, LookAtMatchesHandWorkedExample) {
  const Pose pose = Pose::LookAt({2, 0, 0}, {0, 0, 0}, {0, 0, 1});
  Eigen::Matrix3d expected;
  expected << 0, 1, 0,  //
      0, 0, -1,         //
      -1, 0, 0;
  EXPECT_LT((pose.rotation.toRotationMatrix() - expected).norm(), 1e-12);
  EXPECT_LT((pose.translation - Eigen::Vector3d(0, 0, 2)).norm(), 1e-12);
  EXPECT_LT((pose.Center() - Eigen::Vector3d(2, 0, 0)).norm(), 1e-12);
  EXPECT_LT((pose.ViewDirection() - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-12);

  // The target projects to the principal point; a point above it (+Z world) appears higher in the
  // image (smaller y) and a point towards +Y world appears to the right (larger x).
  const View view{"a.png", Camera::Pinhole(640, 480, 500, 500, 320, 240), pose};
  Eigen::Vector2d pixel;
  ASSERT_TRUE(view.WorldToPixel({0, 0, 0}, &pixel));
  EXPECT_LT((pixel - Eigen::Vector2d(320, 240)).norm(), 1e-9);
  ASSERT_TRUE(view.WorldToPixel({0, 0, 1}, &pixel));
  EXPECT_NEAR(pixel.x(), 320, 1e-9);
  EXPECT_NEAR(pixel.y(), 240 - 500 * 0.5, 1e-9);  // camera point (0, -1, 2)
  ASSERT_TRUE(view.WorldToPixel({0, 1, 0}, &pixel));
  EXPECT_NEAR(pixel.x(), 320 + 500 * 0.5, 1e-9);
  EXPECT_FALSE(view.WorldToPixel({4, 0, 0}, &pixel));  // behind the camera

  // The ray through the principal point is the viewing direction.
  EXPECT_LT((view.PixelRay({320, 240}) - pose.ViewDirection()).norm(), 1e-12);
}

TEST(Pose, LookAtIsOrthonormalForGeneralDirections) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d eye(u(random), u(random), u(random)), target(u(random), u(random), u(random));
    const Pose pose = Pose::LookAt(eye, target, {0, 0, 1});
    EXPECT_NEAR(pose.rotation.norm(), 1.0, 1e-12);
    EXPECT_LT((pose.Center() - eye).norm(), 1e-9);
    const Eigen::Vector3d target_camera = pose.ToCamera(target);
    EXPECT_NEAR(target_camera.x(), 0, 1e-9);
    EXPECT_NEAR(target_camera.y(), 0, 1e-9);
    EXPECT_GT(target_camera.z(), 0);
    // World up appears up in the image: the camera's down axis points against world +Z.
    EXPECT_LE((pose.rotation.conjugate() * Eigen::Vector3d::UnitY()).z(), 1e-12);
    EXPECT_LT((pose.ToWorld(pose.ToCamera(eye + target)) - (eye + target)).norm(), 1e-9);
  }
}

// COLMAP's images.txt example line (https://colmap.github.io/format.html):
//   1 0.851773 0.0165051 0.503764 -0.142941 -0.737434 1.02973 3.74354 1 P1180141.JPG
// QW comes first; the rotation is the Hamilton quaternion's matrix, computed here by hand.
TEST(Pose, ColmapQuaternionOrderAndCenter) {
  const double w = 0.851773, x = 0.0165051, y = 0.503764, z = -0.142941;
  Pose pose;
  pose.rotation = Eigen::Quaterniond(w, x, y, z).normalized();
  pose.translation = {-0.737434, 1.02973, 3.74354};
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  const double a = w / n, b = x / n, c = y / n, d = z / n;
  Eigen::Matrix3d by_hand;
  by_hand << 1 - 2 * (c * c + d * d), 2 * (b * c - a * d), 2 * (b * d + a * c),  //
      2 * (b * c + a * d), 1 - 2 * (b * b + d * d), 2 * (c * d - a * b),         //
      2 * (b * d - a * c), 2 * (c * d + a * b), 1 - 2 * (b * b + c * c);
  EXPECT_LT((pose.rotation.toRotationMatrix() - by_hand).norm(), 1e-12);
  const Eigen::Vector3d center = -by_hand.transpose() * pose.translation;
  EXPECT_LT((pose.Center() - center).norm(), 1e-12);
  EXPECT_LT(pose.ToCamera(center).norm(), 1e-12);
  EXPECT_LT((pose.ViewDirection() - by_hand.row(2).transpose()).norm(), 1e-12);
}

}  // namespace
}  // namespace voltree
