// --levels auto: the finest level is the first whose texel covers at most one photo pixel.
#include <gtest/gtest.h>

#include "core/error.h"
#include "reconstruct/auto_levels.h"
#include "synthetic_scene.h"

namespace voltree {
namespace {

ReconstructInput RingOfSize(int size) {
  ReconstructInput input;
  input.views = testing::RingViews(8, size);
  input.bounds_min = Eigen::Vector3d::Zero();
  input.bounds_max = Eigen::Vector3d::Ones();
  input.source = "ring";
  return input;
}

TEST(AutoLevels, FinestTexelCoversAboutOnePixel) {
  ReconstructOptions options;  // 4x4 texels, 5 % margin: the root cube is 1.1 wide
  // Focal 1.45 x size at distance 3: a root texel covers 1.45 * size * 1.1 / 4 / 3 pixels.
  EXPECT_EQ(LevelsForPhotos(RingOfSize(64), options), 5);   // 8.5 px: level 4 is 0.53 px
  EXPECT_EQ(LevelsForPhotos(RingOfSize(512), options), 8);  // 68 px: level 7 is 0.53 px
  EXPECT_EQ(LevelsForPhotos(RingOfSize(1024), options), 9);
  options.texels = 8;
  EXPECT_EQ(LevelsForPhotos(RingOfSize(512), options), 7);
}

TEST(AutoLevels, PhotosTooSmallForThreeLevelsSaySo) {
  ReconstructOptions options;
  try {
    LevelsForPhotos(RingOfSize(8), options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("8x8"), std::string::npos) << message;
    EXPECT_NE(message.find("too small for even 3"), std::string::npos) << message;
    EXPECT_NE(message.find("--levels"), std::string::npos) << message;
  }
  EXPECT_EQ(LevelsForPhotos(RingOfSize(16), options), 3);
}

TEST(AutoLevels, ReconstructUsesTheResolvedDepth) {
  const testing::Phantom phantom = testing::BlobPhantom(16);
  ReconstructInput input = testing::PhantomInput(phantom, 8, 32);
  ReconstructOptions options;
  options.auto_levels = true;
  options.fit.enabled = false;
  Progress quiet(true);
  EXPECT_EQ(Reconstruct(input, options, &quiet).levels.size(), 4u);  // 4.25 px at the root: level 3 is 0.53 px
}

}  // namespace
}  // namespace voltree
