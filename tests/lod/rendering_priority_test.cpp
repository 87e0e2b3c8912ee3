#include "lod/rendering_priority.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/leaf_separation.h"
#include "lod/seeded_random.h"
#include "lod/stochastic_pruning.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

// A crown of square leaf cards of side `side`, one per centre, each perpendicular to its normal.
TreeMesh CardCrown(const std::vector<Eigen::Vector3f>& centres, const std::vector<Eigen::Vector3f>& normals,
                   float side) {
  TreeMesh mesh;
  Material leaf{.name = "leaves"};
  leaf.alpha_mode = AlphaMode::kMask;
  mesh.materials.push_back(leaf);
  MeshGroup cards{0, {}};
  for (size_t i = 0; i < centres.size(); ++i) {
    const Eigen::Vector3f n = normals[i].normalized();
    const Eigen::Vector3f u = n.unitOrthogonal() * (side / 2), v = n.cross(u);
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    const Eigen::Vector3f corners[] = {-u - v, u - v, u + v, -u + v};
    for (const Eigen::Vector3f& corner : corners) {
      MeshVertex vertex;
      vertex.position = centres[i] + corner;
      vertex.normal = n;
      mesh.vertices.push_back(vertex);
    }
    cards.indices.insert(cards.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  mesh.groups.push_back(cards);
  return mesh;
}

Eigen::Vector3f RandomDirection(SeededRandom& random) {
  const double z = 2 * random.Uniform() - 1, phi = 2 * std::numbers::pi * random.Uniform();
  const double r = std::sqrt(1 - z * z);
  return Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z).cast<float>();
}

double MeanPosition(const std::vector<uint32_t>& order, const std::vector<bool>& selected) {
  double sum = 0;
  int count = 0;
  for (size_t k = 0; k < order.size(); ++k)
    if (selected[order[k]]) sum += static_cast<double>(k), ++count;
  return sum / std::max(count, 1);
}

RenderingPriorityOptions WideRadius() {
  RenderingPriorityOptions options;
  options.radius_fraction = 0.2;  // a 400-leaf crown is far sparser than a real one
  return options;
}

TEST(RenderingPriority, TheOrderIsDeterministicAPermutationAndNotTheRandomOne) {
  const TreeMesh mesh = test::SyntheticFoliage(300, 0.05f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  ASSERT_EQ(leaves.size(), 300u);
  const std::vector<uint32_t> order = RenderingPriorityOrder(mesh, leaves, WideRadius());
  EXPECT_EQ(order, RenderingPriorityOrder(mesh, leaves, WideRadius()));
  std::vector<uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  const std::vector<uint32_t> random = RandomLeafOrder(leaves.size(), 1);
  size_t same = 0;
  for (size_t k = 0; k < order.size(); ++k) same += order[k] == random[k];
  EXPECT_LT(same, 10u);  // a random permutation shares about one position with another
  // The jitter's seed changes only near-ties: a different permutation.
  RenderingPriorityOptions other = WideRadius();
  other.seed = 2;
  EXPECT_NE(order, RenderingPriorityOrder(mesh, leaves, other));
}

// A ball crown: leaves on the outer shell face outward (their normal is the hull's), the core's are
// oriented at random. Both terms keep the shell longer: it faces the way the hull does, and it is
// less dense (half its metaball neighbourhood is outside the crown).
TEST(RenderingPriority, OuterLeavesFacingOutwardAreKeptLonger) {
  SeededRandom random(3);
  std::vector<Eigen::Vector3f> centres, normals;
  std::vector<bool> shell;
  const Eigen::Vector3f middle(0, 0, 2);
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector3f direction = RandomDirection(random);
    const bool outer = i % 2 == 0;
    const float radius = outer ? 1.0f : static_cast<float>(0.6 * std::cbrt(random.Uniform()));
    centres.push_back(middle + radius * direction);
    normals.push_back(outer ? direction : RandomDirection(random));
    shell.push_back(outer);
  }
  const TreeMesh mesh = CardCrown(centres, normals, 0.05f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  ASSERT_EQ(leaves.size(), centres.size());
  const double radius = 0.2 * 2.05;  // radius_fraction of the crown's height

  // The hull's normal at the shell is radial, so the shell's cards face it.
  const std::vector<Eigen::Vector3f> hull = HullNormals(leaves, radius, 3);
  const std::vector<double> silhouette = SilhouetteSurvival(LeafNormals(mesh, leaves), hull);
  double facing = 0, core_facing = 0;
  for (size_t i = 0; i < leaves.size(); ++i) (shell[i] ? facing : core_facing) += silhouette[i] / 200;
  EXPECT_GT(facing, 0.8);       // the hull is a union of balls, voxelized: its normal wobbles
  EXPECT_LT(core_facing, 0.7);  // random orientations: |cos| averages 0.5

  const std::vector<double> density = DensitySurvival(leaves, radius);
  double shell_density = 0, core_density = 0;
  for (size_t i = 0; i < leaves.size(); ++i) (shell[i] ? shell_density : core_density) += density[i] / 200;
  EXPECT_GT(shell_density, core_density + 0.1);

  const std::vector<uint32_t> order = RenderingPriorityOrder(mesh, leaves, WideRadius());
  std::vector<bool> core(shell.size());
  for (size_t i = 0; i < shell.size(); ++i) core[i] = !shell[i];
  EXPECT_LT(MeanPosition(order, shell) + 100, MeanPosition(order, core));
  // Each heuristic alone also keeps the shell longer.
  for (PriorityTerms terms : {PriorityTerms::kSilhouette, PriorityTerms::kDensity}) {
    RenderingPriorityOptions alone = WideRadius();
    alone.terms = terms;
    const std::vector<uint32_t> by_term = RenderingPriorityOrder(mesh, leaves, alone);
    EXPECT_LT(MeanPosition(by_term, shell) + 50, MeanPosition(by_term, core)) << static_cast<int>(terms);
  }
  // The random order does not prefer either (both near the middle, 199.5).
  const std::vector<uint32_t> random_order = RandomLeafOrder(leaves.size(), 1);
  EXPECT_NEAR(MeanPosition(random_order, shell), MeanPosition(random_order, core), 40);
}

// Density normalization thins a clump before it touches the isolated leaves around it.
TEST(RenderingPriority, DenseRegionsArePrunedFirst) {
  std::vector<Eigen::Vector3f> centres, normals;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) centres.push_back({0.02f * i, 0.02f * j, 1.0f});  // the clump
  for (int i = 0; i < 6; ++i) centres.push_back({1.0f + i, 0.0f, 1.0f});          // isolated
  normals.assign(centres.size(), Eigen::Vector3f::UnitZ());
  const TreeMesh mesh = CardCrown(centres, normals, 0.01f);
  const std::vector<double> survival = DensitySurvival(SeparateLeaves(mesh), 0.5);
  const double isolated = *std::min_element(survival.begin() + 25, survival.end());
  // Every clump leaf but one (the last of them is as isolated as the others) goes first.
  EXPECT_GE(std::count_if(survival.begin(), survival.begin() + 25, [&](double s) { return s < isolated; }), 24);
}

TEST(RenderingPriority, CombinationSquaresTheSilhouetteTermAndNormalizes) {
  const std::vector<double> combined = CombinedSurvival({0.0, 1.0, 0.5, 1.0}, {0.0, 0.0, 1.0, 1.0});
  // 0, 1, 1.25, 2 scaled by the range 2.
  EXPECT_DOUBLE_EQ(combined[0], 0);
  EXPECT_DOUBLE_EQ(combined[1], 0.5);
  EXPECT_DOUBLE_EQ(combined[2], 0.625);
  EXPECT_DOUBLE_EQ(combined[3], 1);
  EXPECT_EQ(PriorityLeafOrder(combined, 0, 1), (std::vector<uint32_t>{3, 2, 1, 0}));
  EXPECT_THROW(CombinedSurvival({1.0}, {}), Error);
}

TEST(RenderingPriority, BadOptionsAreRefused) {
  RenderingPriorityOptions options;
  options.radius_fraction = 0;
  EXPECT_THROW(options.Check(), Error);
  options = {};
  options.jitter = -0.1;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_THROW(DensitySurvival({}, 0), Error);
}

}  // namespace
}  // namespace voltree
