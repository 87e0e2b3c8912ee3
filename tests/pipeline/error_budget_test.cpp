// The error budget's pieces worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "pipeline/error_budget.h"

namespace voltree {
namespace {

TEST(ErrorBudget, PartRecallCountsThePartsPixelsTheRenderCovers) {
  // A 4 x 1 strip: bark at x = 0, 1 (coverage 255 and 128), leaves at x = 2 (200), nothing at 3.
  Image8 parts(4, 1, 3);
  parts.at(0, 0, 0) = 255, parts.at(1, 0, 0) = 128, parts.at(2, 0, 1) = 200, parts.at(3, 0, 0) = 127;
  Image8 render(4, 1, 4);
  render.at(0, 0, 3) = 255;  // covers the first bark pixel
  render.at(1, 0, 3) = 127;  // alpha 0.498: not covered
  render.at(2, 0, 3) = 200;  // covers the leaf
  EXPECT_DOUBLE_EQ(PartRecall(render, parts, 0, 0.5f), 0.5);
  EXPECT_DOUBLE_EQ(PartRecall(render, parts, 1, 0.5f), 1.0);
  parts.at(2, 0, 1) = 0;
  EXPECT_TRUE(std::isnan(PartRecall(render, parts, 1, 0.5f)));  // no leaf shows: no figure
  EXPECT_THROW(PartRecall(render, Image8(3, 1, 3), 0, 0.5f), Error);
}

TEST(ErrorBudget, TableMarksWhatWasNotMeasured) {
  const double nan = std::nan("");
  const std::string table = BudgetTable({{"volume", ViewSet::kInput, 3, nan, 20.5, 0.9, 0.8, nan, nan},
                                         {"lod", ViewSet::kHeldOut, 2, 30.25, 21.0, 0.95, 0.85, 0.7, 0.9}});
  EXPECT_NE(table.find("volume      input         3         -       20.50  0.900  0.800       -       -"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("lod         held_out      2     30.25       21.00  0.950  0.850   0.700   0.900"),
            std::string::npos)
      << table;
}

}  // namespace
}  // namespace voltree
