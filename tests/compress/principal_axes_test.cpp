// Principal axes: orthonormal, largest variance first, and the projections they give.
#include "compress/principal_axes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace voltree {
namespace {

TEST(PrincipalAxes, FindsTheStretchedDirectionsInOrder) {
  // Spread 10 along (1, 1, 0, 0)/sqrt2, 3 along e3, 0.1 elsewhere.
  std::mt19937_64 rng(4);
  std::normal_distribution<float> normal(0, 1);
  TrainingSet set;
  set.dimension = 4;
  for (int i = 0; i < 5000; ++i) {
    const float a = 10 * normal(rng), b = 3 * normal(rng);
    set.vectors.insert(set.vectors.end(), {a / std::sqrt(2.f) + 0.1f * normal(rng),
                                           a / std::sqrt(2.f) + 0.1f * normal(rng), b, 0.1f * normal(rng)});
  }
  const PrincipalAxes axes = FindPrincipalAxes(set, 2);
  ASSERT_EQ(axes.count, 2);
  auto component = [&](int axis, int i) { return axes.by_component[size_t(i) * axes.count + axis]; };
  EXPECT_NEAR(std::abs(component(0, 0)), 1 / std::sqrt(2.f), 0.01);
  EXPECT_NEAR(std::abs(component(0, 1)), 1 / std::sqrt(2.f), 0.01);
  EXPECT_NEAR(std::abs(component(1, 2)), 1, 0.01);
  float dot = 0;
  for (int i = 0; i < 4; ++i) dot += component(0, i) * component(1, i);
  EXPECT_NEAR(dot, 0, 1e-5);

  std::vector<float> projected(set.size() * axes.count);
  axes.ProjectAll(set, projected.data());
  for (size_t v = 0; v < set.size(); v += 997)
    for (int a = 0; a < 2; ++a) {
      float expected = 0;
      for (int i = 0; i < 4; ++i) expected += component(a, i) * set.Vector(v)[i];
      EXPECT_NEAR(projected[v * 2 + a], expected, 1e-3);
    }
}

TEST(PrincipalAxes, ClampsToTheDimension) {
  TrainingSet set;
  set.dimension = 3;
  set.vectors = {1, 2, 3, 4, 5, 7, 0, 1, 1};
  EXPECT_EQ(FindPrincipalAxes(set, 14).count, 3);
  EXPECT_EQ(FindPrincipalAxes(TrainingSet{3, {}, {}}, 14).count, 0);
}

}  // namespace
}  // namespace voltree
