// Neubert et al. 2011's occlusion test (sec. 4): the crown's hull samples, the depth of a frame,
// the visible fraction, its hysteresis and the lambda it gives.
#include "lod/occlusion_factor.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "expect_check_names.h"

namespace voltree {
namespace {

// Leaves at the corners of a unit cube centred at (0, 0, 1).
std::vector<Leaf> CubeOfLeaves() {
  std::vector<Leaf> leaves;
  for (int k = 0; k < 8; ++k) {
    Leaf leaf;
    leaf.centre = Eigen::Vector3f(k & 1 ? 0.5f : -0.5f, k & 2 ? 0.5f : -0.5f, k & 4 ? 1.5f : 0.5f);
    leaf.area = 1;
    leaves.push_back(leaf);
  }
  return leaves;
}

// A 64 x 64 pinhole looking along +y from (0, -5, 1).
View FromFiveUnitsSouth() {
  View view;
  view.camera = Camera::Pinhole(64, 64, 64, 64, 32, 32);
  view.pose = Pose::LookAt(Eigen::Vector3d(0, -5, 1), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ());
  return view;
}

// A frame whose every pixel lies `distance` along the view axis.
FrameDepth Wall(double distance) {
  return FrameDepth(FromFiveUnitsSouth(), 64, 64, std::vector<float>(64 * 64, static_cast<float>(distance)));
}

TEST(CrownHullSamples, LieOnTheOuterPlaneOfTheirDirection) {
  const std::vector<Leaf> leaves = CubeOfLeaves();
  const double radius = 0.25;
  const std::vector<CrownSample> samples = CrownHullSamples(leaves, radius, 64, 7);
  ASSERT_EQ(samples.size(), 64u);
  for (const CrownSample& sample : samples) {
    EXPECT_NEAR(sample.normal.norm(), 1.0, 1e-5);
    // Every leaf centre is at least `radius` behind the sample along its normal, and one exactly.
    float nearest = 1e9f;
    for (const Leaf& leaf : leaves) {
      const float behind = sample.normal.dot(sample.point - leaf.centre);
      EXPECT_GE(behind, radius - 1e-5);
      nearest = std::min(nearest, behind);
    }
    EXPECT_NEAR(nearest, radius, 1e-5);
  }
  EXPECT_EQ(CrownHullSamples(leaves, radius, 64, 7)[5].point, samples[5].point);  // seeded
  EXPECT_NE(CrownHullSamples(leaves, radius, 64, 8)[5].point, samples[5].point);
  EXPECT_TRUE(CrownHullSamples({}, radius, 64, 7).empty());
  EXPECT_THROW(CrownHullSamples(leaves, radius, 0, 7), Error);
  EXPECT_THROW(CrownHullSamples(leaves, -1, 4, 7), Error);
}

TEST(FrameDepth, APointInFrontOfTheDepthIsVisibleAndOneBehindIsNot) {
  const FrameDepth wall = Wall(5);  // the plane y = 0
  EXPECT_TRUE(wall.Visible(Eigen::Vector3d(0, -1, 1), 0));
  EXPECT_FALSE(wall.Visible(Eigen::Vector3d(0, 1, 1), 0));
  EXPECT_TRUE(wall.Visible(Eigen::Vector3d(0, 0.5, 1), 0.6));  // within the bias
  EXPECT_TRUE(wall.Visible(Eigen::Vector3d(0, -10, 1), 0));    // behind the camera: unknown, visible
  EXPECT_TRUE(wall.Visible(Eigen::Vector3d(50, 1, 1), 0));     // outside the viewport: visible
  EXPECT_THROW(FrameDepth(FromFiveUnitsSouth(), 64, 64, std::vector<float>(10)), Error);
}

TEST(VisibleFraction, AWallInFrontHidesTheTreeAndOneBehindDoesNot) {
  const std::vector<CrownSample> samples = CrownHullSamples(CubeOfLeaves(), 0.1, 64, 1);
  const OcclusionOptions options;
  const Visibility hidden = VisibleFraction(samples, InstanceTransform{}, 1.0, Wall(3), options);
  EXPECT_GT(hidden.tested, 16);
  EXPECT_LT(hidden.tested, 64);  // the samples facing away are not tested
  EXPECT_EQ(hidden.fraction, 0);
  EXPECT_EQ(VisibleFraction(samples, InstanceTransform{}, 1.0, Wall(20), options).fraction, 1);
  // The same tree moved 20 m to the side is outside the frame: unknown, so visible.
  InstanceTransform aside;
  aside.translation = Eigen::Vector3d(20, 0, 0);
  EXPECT_EQ(VisibleFraction(samples, aside, 1.0, Wall(3), options).fraction, 1);
}

TEST(VisibleFraction, AWallOverTheLeftHalfOfTheFrameHidesTheLeftHalfOfTheCrown) {
  const std::vector<CrownSample> samples = CrownHullSamples(CubeOfLeaves(), 0.1, 256, 1);
  std::vector<float> distances(64 * 64, 20.0f);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 32; ++x) distances[size_t(y) * 64 + x] = 3.0f;
  const View view = FromFiveUnitsSouth();
  const Visibility half = VisibleFraction(samples, InstanceTransform{}, 1.0, FrameDepth(view, 64, 64, distances), {});
  int right = 0, tested = 0;
  for (const CrownSample& sample : samples) {
    if (sample.normal.dot(Eigen::Vector3f(0, -5, 1) - sample.point) <= 0) continue;
    ++tested;
    Eigen::Vector2d pixel;
    ASSERT_TRUE(view.WorldToPixel(sample.point.cast<double>(), &pixel));
    right += pixel.x() >= 32;
  }
  EXPECT_EQ(half.tested, tested);
  EXPECT_NEAR(half.fraction, double(right) / tested, 1e-12);
  EXPECT_GT(half.fraction, 0.3);
  EXPECT_LT(half.fraction, 0.7);
}

TEST(SmoothedVisibility, RisesAtOnceAndFallsPartOfTheWay) {
  EXPECT_EQ(SmoothedVisibility(std::nullopt, 0.2, 0.5), 0.2);  // first test: as measured
  EXPECT_EQ(SmoothedVisibility(0.2, 0.9, 0.5), 0.9);           // a tree coming into view
  EXPECT_DOUBLE_EQ(SmoothedVisibility(1.0, 0.0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(SmoothedVisibility(0.5, 0.0, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(SmoothedVisibility(1.0, 0.0, 1.0), 0.0);
}

TEST(OccludedLambda, ScalesByTheVisibleFractionDownToTheFloor) {
  EXPECT_DOUBLE_EQ(OccludedLambda(0.5, 1, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(OccludedLambda(0.5, 0.4, 0.1), 0.2);
  EXPECT_DOUBLE_EQ(OccludedLambda(0.5, 0, 0.1), 0.05);  // the paper's max(f, 0.1)
  EXPECT_DOUBLE_EQ(OccludedLambda(1, 0.02, 0.1), 0.1);
  EXPECT_THROW(OccludedLambda(0, 0.5, 0.1), Error);
  EXPECT_THROW(OccludedLambda(1.5, 0.5, 0.1), Error);
}

TEST(OcclusionOptions, CheckNamesTheField) {
  OcclusionOptions options;
  EXPECT_NO_THROW(options.Check());
  options.fall = 0;
  testing::ExpectCheckNames(options, "OcclusionOptions.fall");
  options = {};
  options.samples = 0;
  EXPECT_THROW(options.Check(), Error);
  options = {};
  options.min_factor = 0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace voltree
