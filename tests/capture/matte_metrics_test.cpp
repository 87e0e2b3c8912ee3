#include "capture/matte/metrics.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace voltree {
namespace {

TEST(MatteMetrics, AlphamattingConventions) {
  const Image8 truth(100, 50, 1, 0);
  Image8 estimate(100, 50, 1, 0);
  EXPECT_EQ(CompareMattes(estimate, truth).sad, 0.0);
  // 1000 fully wrong pixels of 5000: SAD 1 (thousand), MSE 0.2 -> 200 (x1e3).
  for (int i = 0; i < 1000; ++i) estimate.pixels[i] = 255;
  MatteError error = CompareMattes(estimate, truth);
  EXPECT_DOUBLE_EQ(error.sad, 1.0);
  EXPECT_DOUBLE_EQ(error.mse, 200.0);
  EXPECT_EQ(error.band_pixels, 1000u);
  EXPECT_DOUBLE_EQ(error.mse_band, 1000.0);
  // Half-wrong pixels: |0.5| each.
  Image8 half(100, 50, 1, 0);
  for (int i = 0; i < 2000; ++i) half.pixels[i] = 51;  // 0.2
  error = CompareMattes(half, truth);
  EXPECT_NEAR(error.sad, 0.4, 1e-12);
  EXPECT_NEAR(error.mse, 0.04 * 2000 / 5000 * 1e3, 1e-9);
}

TEST(MatteMetrics, RejectsMismatchedMattes) {
  EXPECT_THROW(CompareMattes(Image8(4, 4, 1), Image8(4, 5, 1)), Error);
  EXPECT_THROW(CompareMattes(Image8(4, 4, 3), Image8(4, 4, 1)), Error);
}

}  // namespace
}  // namespace voltree
