#include "lod/stochastic_pruning.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "lod/leaf_separation.h"
#include "lod/pruned_mesh.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

// The area of every triangle of the leaf material, measured on the built mesh itself.
double LeafTriangleArea(const TreeMesh& mesh) {
  double area = 0;
  for (const MeshGroup& group : mesh.groups) {
    if (!IsLeafMaterial(mesh.materials[group.material])) continue;
    for (size_t t = 0; t + 2 < group.indices.size(); t += 3) {
      const Eigen::Vector3d a = mesh.vertices[group.indices[t]].position.cast<double>();
      const Eigen::Vector3d b = mesh.vertices[group.indices[t + 1]].position.cast<double>();
      const Eigen::Vector3d c = mesh.vertices[group.indices[t + 2]].position.cast<double>();
      area += 0.5 * (b - a).cross(c - a).norm();
    }
  }
  return area;
}

TEST(LeafSeparation, EachCardIsOneLeafWeldedOrNot) {
  for (bool welded : {true, false}) {
    const TreeMesh mesh = test::SyntheticFoliage(40, 0.05f, 3, welded);
    const std::vector<Leaf> leaves = SeparateLeaves(mesh);
    ASSERT_EQ(leaves.size(), 40u) << welded;
    for (const Leaf& leaf : leaves) {
      EXPECT_EQ(leaf.triangles.size(), 2u);
      EXPECT_NEAR(leaf.area, 0.05 * 0.05, 1e-7);
    }
    // The first card's centre is the middle of its square.
    const Eigen::Vector3f corner = mesh.vertices[3].position;
    EXPECT_LT((leaves[0].centre - (corner + Eigen::Vector3f(0.025f, 0, 0.025f))).norm(), 1e-6f);
  }
}

TEST(LeafSeparation, AMeshWithoutLeafMaterialHasNoLeaves) {
  TreeMesh mesh = test::SyntheticFoliage(5, 0.1f);
  mesh.materials[1] = Material{.name = "bark2"};
  EXPECT_TRUE(SeparateLeaves(mesh).empty());
}

TEST(StochasticPruning, KeepsLambdaOfTheLeavesAndTheirArea) {
  const TreeMesh mesh = test::SyntheticFoliage(200, 0.02f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const std::vector<uint32_t> order = RandomLeafOrder(leaves.size(), 11);
  const double full_area = TotalLeafArea(leaves);
  for (double lambda : {1.0, 0.7, 0.5, 0.25, 0.1, 0.013}) {
    const std::vector<LeafDraw> draws = PruneLeaves(order, lambda, CookAreaScale(lambda));
    EXPECT_LE(std::abs(static_cast<double>(draws.size()) - lambda * 200), 0.5 + 1e-9) << lambda;
    const TreeMesh pruned = BuildPrunedMesh(mesh, leaves, draws);
    EXPECT_EQ(pruned.TriangleCount(), 1 + 2 * draws.size()) << lambda;
    // Rounding lambda * N moves the kept area by at most half a leaf's share; with s = 1 / lambda
    // the drawn area is full_area * round(lambda N) / (lambda N).
    const double expected = full_area * static_cast<double>(draws.size()) / (lambda * 200);
    EXPECT_NEAR(LeafTriangleArea(pruned), expected, 1e-4 * expected) << lambda;
    if (std::abs(lambda * 200 - std::round(lambda * 200)) < 1e-9) {
      EXPECT_NEAR(LeafTriangleArea(pruned), full_area, 0.01 * full_area) << lambda;
    }
  }
}

TEST(StochasticPruning, UnscaledLeavesStayWhereTheyWere) {
  const TreeMesh mesh = test::SyntheticFoliage(10, 0.1f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const TreeMesh all = BuildPrunedMesh(mesh, leaves, PruneLeaves(RandomLeafOrder(10, 5), 1.0, 1.0));
  ASSERT_EQ(all.vertices.size(), mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_EQ(all.vertices[i].position, mesh.vertices[i].position);
  EXPECT_EQ(all.groups[1].indices, mesh.groups[1].indices);
}

TEST(StochasticPruning, TheSameSeedGivesTheSameOrderAndMesh) {
  const std::vector<uint32_t> a = RandomLeafOrder(1000, 42), b = RandomLeafOrder(1000, 42);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, RandomLeafOrder(1000, 43));
  std::vector<uint32_t> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  const TreeMesh mesh = test::SyntheticFoliage(100, 0.03f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const TreeMesh one = BuildPrunedMesh(mesh, leaves, PruneLeaves(RandomLeafOrder(100, 9), 0.3, 2.5));
  const TreeMesh two = BuildPrunedMesh(mesh, leaves, PruneLeaves(RandomLeafOrder(100, 9), 0.3, 2.5));
  ASSERT_EQ(one.vertices.size(), two.vertices.size());
  for (size_t i = 0; i < one.vertices.size(); ++i) EXPECT_EQ(one.vertices[i].position, two.vertices[i].position);
  EXPECT_EQ(one.groups[1].indices, two.groups[1].indices);
}

TEST(StochasticPruning, LambdaOutsideZeroToOneIsRefused) {
  for (double lambda : {0.0, -0.5, 1.01, std::nan("")}) {
    EXPECT_THROW(KeptLeafCount(10, lambda), Error) << lambda;
    EXPECT_THROW(CookAreaScale(lambda), Error) << lambda;
  }
  const TreeMesh mesh = test::SyntheticFoliage(3, 0.1f);
  EXPECT_THROW(BuildPrunedMesh(mesh, SeparateLeaves(mesh), {{7, 1.0}}), Error);
  EXPECT_THROW(BuildPrunedMesh(mesh, SeparateLeaves(mesh), {{0, 0.0}}), Error);
}

}  // namespace
}  // namespace voltree
