#include "capture/matte/refine.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace voltree::matte {
namespace {

// A green disc on a blue ground with a thin unknown ring of `unknown_pixels` pixels at most.
struct Tile {
  cv::Mat rgb, estimate, trimap, solve;
};
Tile DiscTile(int unknown_pixels) {
  Tile tile;
  tile.rgb = cv::Mat(96, 96, CV_8UC3, cv::Scalar(200, 60, 40));
  cv::circle(tile.rgb, {48, 48}, 20, cv::Scalar(40, 170, 60), cv::FILLED);
  tile.trimap = cv::Mat(96, 96, CV_8U, cv::Scalar(0));
  cv::circle(tile.trimap, {48, 48}, 20, cv::Scalar(255), cv::FILLED);
  for (int i = 0; i < unknown_pixels; ++i) tile.trimap.at<uint8_t>(48 + i / 4, 68 + i % 4) = 128;
  tile.estimate = cv::Mat(96, 96, CV_32F, cv::Scalar(0.25));
  tile.solve = tile.trimap == 128;
  return tile;
}

// OpenCV's infoFlow crashed the whole process (a segfault in run, after every photo had been
// matted) on a tile of one photo whose context held a single unknown pixel.
TEST(InfoFlowOnTiles, ATileWithAFewUnknownPixelsKeepsItsEstimateInsteadOfCrashing) {
  for (int unknown : {1, 2, 4, kMinInfoFlowUnknown - 1}) {
    const Tile tile = DiscTile(unknown);
    const cv::Mat alpha = InfoFlowOnTiles(tile.rgb, tile.estimate, tile.trimap, tile.solve, 64);
    EXPECT_FLOAT_EQ(alpha.at<float>(48, 68), 0.25f) << unknown << " unknown pixels";
  }
}

TEST(InfoFlowOnTiles, EnoughUnknownPixelsAreSolved) {
  const Tile tile = DiscTile(2 * kMinInfoFlowUnknown);
  const cv::Mat alpha = InfoFlowOnTiles(tile.rgb, tile.estimate, tile.trimap, tile.solve, 64);
  // The unknown pixels lie on the green side of the disc's edge (x 68..71, inside radius 20 only
  // at x = 68): solved, they move away from the estimate.
  double moved = 0;
  for (int i = 0; i < 2 * kMinInfoFlowUnknown; ++i) moved += std::abs(alpha.at<float>(48 + i / 4, 68 + i % 4) - 0.25f);
  EXPECT_GT(moved / (2 * kMinInfoFlowUnknown), 0.2);
}

}  // namespace
}  // namespace voltree::matte
