// Carving with one wrong matte: the strict visual hull loses the whole tree to it, carving where two
// photos see a cell empty keeps every cell the right mattes keep and still carves the rest.
#include <gtest/gtest.h>

#include <algorithm>

#include "reconstruct/carve.h"
#include "synthetic_scene.h"

namespace voltree {
namespace {

TEST(CarveCells, TwoEmptyViewsSurviveOneWrongMatte) {
  const testing::Phantom phantom = testing::BlobPhantom(8);
  ReconstructInput input = testing::PhantomInput(phantom, 12, 48);
  const GridFrame frame{Eigen::Vector3d::Zero(), 1.0, 2};
  const int level = 3;  // 8^3
  const std::vector<CellCoord> all = testing::EveryCell(8);
  auto carve = [&](int empty_views) {
    std::vector<MatteStats> mattes;
    for (const Image8& m : input.mattes) mattes.emplace_back(m, 5);
    return CarveCells(frame, level, all, input.views, mattes, empty_views);
  };
  const std::vector<CellCoord> strict = carve(1);
  ASSERT_GT(strict.size(), 20u);
  ASSERT_LT(strict.size(), all.size() / 2);

  // One photo's matte misses the tree altogether.
  std::fill(input.mattes[0].pixels.begin(), input.mattes[0].pixels.end(), uint8_t(0));
  const std::vector<CellCoord> strict_wrong = carve(1), tolerant_wrong = carve(2);
  std::printf("%zu cells: strict hull %zu, with one wrong matte %zu strict and %zu tolerant\n", all.size(),
              strict.size(), strict_wrong.size(), tolerant_wrong.size());
  EXPECT_LT(strict_wrong.size(), strict.size() / 4);
  EXPECT_TRUE(std::includes(tolerant_wrong.begin(), tolerant_wrong.end(), strict.begin(), strict.end(), CellLess));
  EXPECT_LT(tolerant_wrong.size(), all.size() / 2);
}

}  // namespace
}  // namespace voltree
