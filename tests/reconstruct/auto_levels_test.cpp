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

// `run` and `demo` deepen the octree beyond its default where the photos fill more levels and the
// asset is predicted to fit the byte budget: about 2 bytes per billboard, a billboard per view
// and cell, the next level 4 times the finest's cells.
TEST(Deepening, AddsTheLevelsThePhotosFillWhileTheBudgetHoldsThem) {
  const testing::Phantom phantom = testing::BlobPhantom(16);
  const ReconstructInput input = testing::PhantomInput(phantom, 8, 32);  // the photos fill 4 levels
  ReconstructOptions options;
  options.levels = 3;
  options.fit.enabled = false;
  Progress quiet(true);
  EXPECT_EQ(Reconstruct(input, options, &quiet).levels.size(), 3u) << "deepening is off by default";
  options.deepen_within_bytes = uint64_t(1) << 30;
  const Volume deep = Reconstruct(input, options, &quiet);
  ASSERT_EQ(deep.levels.size(), 4u) << "no deeper than the photos fill";
  EXPECT_FALSE(deep.levels[3].cells.empty());
  // The prediction is about the cells of levels 0..2 plus 4 times level 2's, at 2 bytes for each
  // of the 8 views' billboards (counted before the hierarchy is rebuilt from the finest level, so
  // a little off the volume's): a budget a fifth above it deepens, a fifth below does not.
  const Volume shallow = [&] {
    options.deepen_within_bytes = 0;
    return Reconstruct(input, options, &quiet);
  }();
  size_t predicted = 4 * shallow.levels[2].cells.size();
  for (const VolumeLevel& level : shallow.levels) predicted += level.cells.size();
  options.deepen_within_bytes = predicted * 8 * 2 * 6 / 5;
  EXPECT_EQ(Reconstruct(input, options, &quiet).levels.size(), 4u);
  options.deepen_within_bytes = predicted * 8 * 2 * 4 / 5;
  EXPECT_EQ(Reconstruct(input, options, &quiet).levels.size(), 3u);
  // --levels auto is the photos' depth alone.
  options.auto_levels = true;
  options.deepen_within_bytes = 1;
  EXPECT_EQ(Reconstruct(input, options, &quiet).levels.size(), 4u);
}

}  // namespace
}  // namespace voltree
