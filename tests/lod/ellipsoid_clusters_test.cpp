#include "lod/ellipsoid_clusters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/leaf_separation.h"
#include "lod/seeded_random.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

// Three blobs of leaf centres of different sizes and shapes, 120 leaves each.
std::vector<Eigen::Vector3d> ThreeBlobs(const std::vector<Eigen::Vector3d>& means) {
  SeededRandom random(17);
  const auto normal = [&random] {  // Box-Muller
    const double u = std::max(random.Uniform(), 1e-12), v = random.Uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
  };
  const Eigen::Vector3d spreads[3] = {{0.08, 0.08, 0.08}, {0.15, 0.04, 0.04}, {0.05, 0.05, 0.12}};
  std::vector<Eigen::Vector3d> points;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 120; ++i)
      points.push_back(means[c] + Eigen::Vector3d(normal(), normal(), normal()).cwiseProduct(spreads[c]));
  return points;
}

TEST(EllipsoidClusters, EmRecoversTheMeansOfThreeClustersWithinFivePercentOfTheExtent) {
  const std::vector<Eigen::Vector3d> means = {{0, 0, 1}, {1, 0.2, 1.2}, {0.4, 0.9, 1.6}};
  const std::vector<Eigen::Vector3d> points = ThreeBlobs(means);
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double extent = (hi - lo).norm();
  const GaussianMixture mixture =
      FitGaussianMixture(points, std::vector<double>(points.size(), 1.0), 3, EllipsoidClusterOptions{});
  ASSERT_EQ(mixture.components.size(), 3u);
  for (const Eigen::Vector3d& truth : means) {
    double nearest = 1e30;
    for (const GaussianComponent& c : mixture.components) nearest = std::min(nearest, (c.mean - truth).norm());
    EXPECT_LT(nearest, 0.05 * extent) << truth.transpose();
  }
  for (const GaussianComponent& c : mixture.components) EXPECT_NEAR(c.weight, 1.0 / 3, 0.02);
}

TEST(EllipsoidClusters, TheSameSeedGivesTheSameFit) {
  const std::vector<Eigen::Vector3d> points = ThreeBlobs({{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}});
  const std::vector<double> weights(points.size(), 1.0);
  EllipsoidClusterOptions options;
  options.seed = 9;
  const GaussianMixture a = FitGaussianMixture(points, weights, 5, options);
  const GaussianMixture b = FitGaussianMixture(points, weights, 5, options);
  for (size_t j = 0; j < 5; ++j) {
    EXPECT_EQ(a.components[j].mean, b.components[j].mean);
    EXPECT_EQ(a.components[j].covariance, b.components[j].covariance);
  }
}

TEST(EllipsoidClusters, FewerLeavesThanClustersIsRefusedByEmAndClampedByTheHierarchy) {
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  try {
    FitGaussianMixture(two, {1.0, 1.0}, 3, EllipsoidClusterOptions{});
    FAIL();
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("3 clusters of 2 leaves"), std::string::npos) << error.what();
  }
  const TreeMesh mesh = test::SyntheticFoliage(6, 0.05f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const std::vector<EllipsoidLevel> levels =
      BuildEllipsoidHierarchy(leaves, std::vector<Eigen::Vector3f>(leaves.size(), Eigen::Vector3f::Ones()), {});
  ASSERT_EQ(levels.size(), 3u);  // 1, 4, then the 6 leaves instead of 16
  EXPECT_EQ(levels.back().clusters, 6);
  EXPECT_TRUE(BuildEllipsoidHierarchy({}, {}, {}).empty());  // no leaves, no ellipsoids
}

TEST(EllipsoidClusters, SmallerTreesDrawCoarserLevels) {
  const TreeMesh mesh = test::SyntheticFoliage(300, 0.03f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  EllipsoidClusterOptions options;
  options.max_clusters = 64;
  const std::vector<EllipsoidLevel> levels =
      BuildEllipsoidHierarchy(leaves, std::vector<Eigen::Vector3f>(leaves.size(), Eigen::Vector3f::Ones()), options);
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_EQ(EllipsoidLevelFor(levels, 1000, 5), levels.size() - 1);
  EXPECT_EQ(EllipsoidLevelFor(levels, 2, 5), 0u);
  EXPECT_LE(EllipsoidLevelFor(levels, 30, 5), EllipsoidLevelFor(levels, 100, 5));
  // The surface: a closed mesh per ellipsoid, normals of unit length.
  const std::vector<PointPrimitive> surface = EllipsoidSurface(levels[1].ellipsoids, 12);
  EXPECT_EQ(surface.size(), levels[1].ellipsoids.size() * 12 * (2 * 6 - 2) * 3);
  for (const PointPrimitive& corner : surface) EXPECT_NEAR(corner.normal.norm(), 1, 1e-4);
}

TEST(EllipsoidClusters, BadOptionsAreNamed) {
  EllipsoidClusterOptions options;
  options.max_clusters = 0;
  try {
    options.Check();
    FAIL();
  } catch (const OptionError& error) {
    EXPECT_EQ(error.field(), "EllipsoidClusterOptions.max_clusters");
  }
}

}  // namespace
}  // namespace voltree
