#include "lod/pr_optimal_scale.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "lod/screen_size_rule.h"

namespace voltree {
namespace {

TEST(PrOptimalScale, ScoreIsOneMinusTheDistanceToTheIdealCorner) {
  EXPECT_DOUBLE_EQ(PrScore(1, 1), 1);
  EXPECT_DOUBLE_EQ(PrScore(1, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(PrScore(0.7, 0.6), 0.5);  // |(0.3, 0.4)| = 0.5
  EXPECT_NEAR(PrScore(0, 0), 1 - std::sqrt(2.0), 1e-12);
}

// Three scales of a hand-made case: too small loses recall, too large loses precision.
// Q: 1 - 0.5 = 0.5; 1 - |(0.1, 0.1)| = 0.859; 1 - |(0.4, 0)| = 0.6.
TEST(PrOptimalScale, TheChosenScaleIsTheArgmaxOfThePrScore) {
  const std::vector<ScaleTrial> trials = {{1.0, 1.0, 0.5}, {2.0, 0.9, 0.9}, {4.0, 0.6, 1.0}};
  EXPECT_DOUBLE_EQ(BestScaleTrial(trials).area_scale, 2.0);
  // A tie goes to the smaller scale (fewer false positives for the same score).
  EXPECT_DOUBLE_EQ(BestScaleTrial({{3.0, 0.5, 1.0}, {1.5, 1.0, 0.5}}).area_scale, 1.5);
  EXPECT_THROW(BestScaleTrial({}), Error);
}

TEST(PrOptimalScale, CandidatesRunFromNoScalingPastCooks) {
  const std::vector<double> scales = CandidateAreaScales(0.25);
  EXPECT_DOUBLE_EQ(scales.front(), 1.0);
  EXPECT_NEAR(scales[10], 4.0, 1e-12);  // t = 1: Cook's 1 / lambda
  EXPECT_GT(scales.back(), 4.0);
  EXPECT_EQ(CandidateAreaScales(1.0).size(), 1u);
  EXPECT_THROW(CandidateAreaScales(0), Error);
}

TEST(ScreenSizeRule, LambdaIsTheSquareOfTheRelativeSizeAboveTheFloor) {
  EXPECT_DOUBLE_EQ(LambdaForScreenSize(512, 512, 0.01), 1.0);
  EXPECT_DOUBLE_EQ(LambdaForScreenSize(256, 512, 0.01), 0.25);
  EXPECT_DOUBLE_EQ(LambdaForScreenSize(32, 512, 0.01), 0.01);  // (1/16)^2 < 0.01
  EXPECT_THROW(LambdaForScreenSize(600, 512, 0.01), Error);
  EXPECT_THROW(LambdaForScreenSize(0, 512, 0.01), Error);
  EXPECT_THROW(LambdaForScreenSize(64, 512, 0), Error);
  EXPECT_THROW(LambdaForScreenSize(64, 512, 1.5), Error);
}

}  // namespace
}  // namespace voltree
