#include "lod/colour_correction.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "lod/leaf_separation.h"
#include "lod/stochastic_pruning.h"
#include "lod/surface_colour.h"
#include "lod/synthetic_foliage.h"

namespace voltree {
namespace {

// Every leaf tinted with its own colour, from dark red to bright green.
TreeMesh TintedFoliage() {
  TreeMesh mesh = test::SyntheticFoliage(200, 0.05f);
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  for (size_t i = 0; i < leaves.size(); ++i) {
    const float t = static_cast<float>(i % 17) / 16.0f;
    for (uint32_t triangle : leaves[i].triangles)
      for (int corner = 0; corner < 3; ++corner)
        mesh.vertices[mesh.groups[leaves[i].group].indices[3 * triangle + corner]].tint = {0.8f - 0.6f * t,
                                                                                           0.2f + 0.7f * t, 0.3f};
  }
  return mesh;
}

Eigen::Vector3d Mean(const std::vector<Eigen::Vector3f>& colours, const std::vector<double>& weights) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0;
  for (size_t i = 0; i < colours.size(); ++i) sum += weights[i] * colours[i].cast<double>(), total += weights[i];
  return sum / total;
}

TEST(ColourCorrection, SurvivorsGetTheFullMeanAndSqrtLambdaOfTheirContrast) {
  const TreeMesh mesh = TintedFoliage();
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const std::vector<Eigen::Vector3f> colours = LeafColours(mesh, leaves);
  // A biased survivor set: the first quarter of the leaves, mostly one end of the gradient.
  std::vector<uint32_t> order(leaves.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return colours[a].x() > colours[b].x(); });
  const double lambda = 0.25;
  const std::vector<LeafDraw> draws = PruneLeaves(order, lambda, 4.0);
  const std::vector<Eigen::Vector3f> corrected = CorrectedLeafColours(colours, leaves, draws, ContrastFactor(lambda));
  ASSERT_EQ(corrected.size(), draws.size());

  std::vector<double> areas, drawn;
  std::vector<Eigen::Vector3f> kept;
  for (const Leaf& leaf : leaves) areas.push_back(leaf.area);
  for (const LeafDraw& draw : draws) drawn.push_back(leaves[draw.leaf].area * 4), kept.push_back(colours[draw.leaf]);
  const Eigen::Vector3d full = Mean(colours, areas), before = Mean(kept, drawn), after = Mean(corrected, drawn);
  EXPECT_GT((before - full).norm(), 0.05);  // the survivors were biased
  EXPECT_LT((after - full).norm(), 1e-5);
  for (size_t k = 0; k < draws.size(); ++k)  // deviations shrink by sqrt(0.25) = 0.5
    EXPECT_LT(((corrected[k].cast<double>() - after) - 0.5 * (kept[k].cast<double>() - before)).norm(), 1e-5);

  // Through the tints: the recoloured mesh's leaves have the corrected colours.
  const std::vector<Eigen::Vector3f> recoloured =
      LeafColours(WithLeafColours(mesh, leaves, draws, colours, corrected), leaves);
  for (size_t k = 0; k < draws.size(); ++k) EXPECT_LT((recoloured[draws[k].leaf] - corrected[k]).norm(), 1e-5) << k;
}

TEST(ColourCorrection, AllLeavesAtFullContrastAreUnchanged) {
  const TreeMesh mesh = TintedFoliage();
  const std::vector<Leaf> leaves = SeparateLeaves(mesh);
  const std::vector<Eigen::Vector3f> colours = LeafColours(mesh, leaves);
  const std::vector<LeafDraw> draws = PruneLeaves(RandomLeafOrder(leaves.size(), 1), 1.0, 1.0);
  const std::vector<Eigen::Vector3f> corrected = CorrectedLeafColours(colours, leaves, draws, ContrastFactor(1));
  for (size_t k = 0; k < draws.size(); ++k) EXPECT_LT((corrected[k] - colours[draws[k].leaf]).norm(), 1e-5);
  EXPECT_THROW(CorrectedLeafColours(colours, leaves, draws, 1.5), Error);
  EXPECT_THROW(ContrastFactor(0), Error);
}

}  // namespace
}  // namespace voltree
