#include "lod/detail_level_selection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/progress.h"
#include "lod/lod_bench.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

TEST(DetailLevelSelection, TheSampleLambdasAreThePapers) {
  const std::vector<double> all = DetailLevelLambdas(0.01);
  ASSERT_EQ(all.size(), 19u);
  EXPECT_DOUBLE_EQ(all.front(), 0.01);
  EXPECT_NEAR(all[8], 0.09, 1e-12);
  EXPECT_NEAR(all[9], 0.1, 1e-12);
  EXPECT_NEAR(all.back(), 1.0, 1e-12);
  EXPECT_EQ(DetailLevelLambdas(0.05).front(), 0.05);
  EXPECT_THROW(DetailLevelLambdas(0), Error);
}

// By hand: Q rises from 0.6 at lambda 0.1 to 0.8 at 0.2; Cook's quality 0.75 is reached 3/4 of
// the way, at lambda 0.175; the scale is interpolated log-log between 8 and 4.
TEST(DetailLevelSelection, TheSmallestLambdaThatMatchesTheTargetIsInterpolated) {
  const std::vector<LevelSample> samples = {{0.25, 3, 0.85}, {0.1, 8, 0.6}, {0.2, 4, 0.8}, {0.09, 9, 0.7}};
  const LevelSample matched = QualityMatchedLevel(samples, 0.75);
  EXPECT_NEAR(matched.lambda, 0.175, 1e-12);
  const double t = std::log(0.175 / 0.1) / std::log(2.0);
  EXPECT_NEAR(matched.area_scale, 8 * std::pow(0.5, t), 1e-9);
  EXPECT_DOUBLE_EQ(matched.quality, 0.75);
  // The smallest sample already matches: it is taken as it is.
  EXPECT_DOUBLE_EQ(QualityMatchedLevel(samples, 0.55).lambda, 0.09);
  // Nothing reaches the target: the best sample.
  EXPECT_DOUBLE_EQ(QualityMatchedLevel(samples, 0.9).lambda, 0.25);
  EXPECT_THROW(QualityMatchedLevel({}, 0.5), Error);
}

// On a tiny tree, end to end: at each pruned size the bench walks the sample lambdas from Cook's
// and draws the matched level, which is at least as good as Cook's on the input views and, where
// it is below Cook's lambda, lies between a sample that met the target and one that did not.
TEST(DetailLevelSelection, TheBenchDrawsTheQualityMatchedLevelOnATinyTree) {
  LodBenchOptions options;
  options.studio.width = options.studio.height = 48;
  options.studio.held_out = 2;
  options.sizes = {48, 24, 12};
  options.top_views = 0;
  options.preprocess_views = 2;
  options.ellipsoids.max_clusters = 8;
  Progress quiet(true);
  const LodBenchResult result = RunLodBench(test::SyntheticFoliage(300, 0.06f), "tiny", options, quiet);
  ASSERT_EQ(result.level_selections.size(), 3u);
  for (const LevelSelection& selection : result.level_selections) {
    SCOPED_TRACE(selection.size);
    ASSERT_FALSE(selection.samples.empty());
    EXPECT_DOUBLE_EQ(selection.samples.front().lambda, selection.cook_lambda);
    if (selection.size == 48) {  // lambda 1: the full mesh, nothing tried
      EXPECT_EQ(selection.samples.size(), 1u);
      EXPECT_DOUBLE_EQ(selection.matched.lambda, 1);
      continue;
    }
    EXPECT_GE(selection.samples.size(), 2u);
    if (selection.samples.front().quality >= selection.target) {
      EXPECT_LE(selection.matched.lambda, selection.cook_lambda);
      EXPECT_GE(selection.matched.quality, selection.target - 1e-12);
      const auto below = std::find_if(selection.samples.begin(), selection.samples.end(),
                                      [&](const LevelSample& s) { return s.lambda < selection.matched.lambda; });
      if (below != selection.samples.end()) {
        EXPECT_LT(below->quality, selection.target);
      }
    }
    bool drawn = false;
    for (const LodBenchRow& row : result.rows)
      if (row.method == "neubert-matched" && row.size == selection.size) {
        drawn = true;
        EXPECT_DOUBLE_EQ(row.lambda, selection.matched.lambda);
        EXPECT_DOUBLE_EQ(row.area_scale, selection.matched.area_scale);
      }
    EXPECT_TRUE(drawn);
  }
}

}  // namespace
}  // namespace voltree
