#include "samples/studio_rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace voltree {
namespace {

std::vector<Eigen::Vector3d> Corners(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
  return corners;
}

double ElevationDegrees(const View& view, const Eigen::Vector3d& target) {
  const Eigen::Vector3d d = (view.pose.Center() - target).normalized();
  return std::asin(d.z()) * 180 / std::numbers::pi;
}

TEST(StudioRig, EveryCameraSeesTheWholeTree) {
  StudioOptions options;
  options.width = 640;
  options.height = 480;
  for (const auto& [lo, hi] : {std::pair{Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 9)},  // tall
                               std::pair{Eigen::Vector3d(-6, -5, 0), Eigen::Vector3d(6, 5, 4)},  // wide
                               std::pair{Eigen::Vector3d(-0.1, -0.1, 0), Eigen::Vector3d(0.1, 0.1, 0.3)}}) {
    const StudioRig rig = MakeStudioRig(lo, hi, options);
    ASSERT_EQ(rig.inputs.size(), 24u);
    ASSERT_EQ(rig.held_out.size(), 8u);
    double nearest_edge = 1e9;
    for (const std::vector<View>* views : {&rig.inputs, &rig.held_out})
      for (const View& view : *views) {
        EXPECT_GT(view.pose.Center().z(), 0) << "camera below the ground";
        for (const Eigen::Vector3d& corner : Corners(lo, hi)) {
          Eigen::Vector2d pixel;
          ASSERT_TRUE(view.WorldToPixel(corner, &pixel));
          EXPECT_GT(pixel.x(), 0);
          EXPECT_GT(pixel.y(), 0);
          EXPECT_LT(pixel.x(), options.width);
          EXPECT_LT(pixel.y(), options.height);
          nearest_edge =
              std::min({nearest_edge, pixel.x(), pixel.y(), options.width - pixel.x(), options.height - pixel.y()});
        }
      }
    // The framing is tight: some corner comes within 12% of the frame's half height of an edge.
    EXPECT_LT(nearest_edge, 0.12 * options.height / 2) << hi.transpose();
  }
}

TEST(StudioRig, RingsAndHeldOutViewsAreDistinct) {
  StudioOptions options;
  options.views = 10;
  options.rings = 3;
  options.held_out = 4;
  const Eigen::Vector3d lo(-1, -1, 0), hi(1, 1, 3);
  const StudioRig rig = MakeStudioRig(lo, hi, options);
  ASSERT_EQ(rig.inputs.size(), 10u);
  EXPECT_EQ(rig.inputs.front().name, "view_000.png");
  EXPECT_EQ(rig.held_out.back().name, "held_003.png");
  // Rings of 4, 3, 3 views at 5, 20 and 35 degrees.
  EXPECT_NEAR(ElevationDegrees(rig.inputs[0], rig.target), 5, 1e-9);
  EXPECT_NEAR(ElevationDegrees(rig.inputs[4], rig.target), 20, 1e-9);
  EXPECT_NEAR(ElevationDegrees(rig.inputs[9], rig.target), 35, 1e-9);
  for (const View& held : rig.held_out) {
    const double elevation = ElevationDegrees(held, rig.target);
    EXPECT_TRUE(std::abs(elevation - 12.5) < 1e-9 || std::abs(elevation - 27.5) < 1e-9) << elevation;
    for (const View& input : rig.inputs) EXPECT_GT((held.pose.Center() - input.pose.Center()).norm(), 0.1);
  }
}

TEST(StudioRig, SeedTurnsTheRings) {
  StudioOptions options;
  const Eigen::Vector3d lo(-1, -1, 0), hi(1, 1, 3);
  const StudioRig a = MakeStudioRig(lo, hi, options);
  EXPECT_EQ(a.inputs[3].pose.Center(), MakeStudioRig(lo, hi, options).inputs[3].pose.Center());
  options.seed = 2;
  EXPECT_GT((a.inputs[3].pose.Center() - MakeStudioRig(lo, hi, options).inputs[3].pose.Center()).norm(), 0.01);
}

TEST(StudioOptions, RejectsBadValues) {
  StudioOptions options;
  options.rings = 0;
  EXPECT_THROW(options.Check(), Error);
  options = {};
  options.camera_model = CameraModel::kOpenCV;
  options.distortion = {0.1};  // OPENCV takes four
  EXPECT_THROW(options.Check(), Error);
  options.distortion = {0.1, 0, 0, 0};
  EXPECT_NO_THROW(options.Check());
  EXPECT_EQ(MakeStudioCamera(options).params.size(), 8u);
  options = {};
  options.supersample = 0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace voltree
