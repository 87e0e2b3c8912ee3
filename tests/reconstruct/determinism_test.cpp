// Same inputs -> identical volume/ bytes, with 1 or 2 threads.
#include <gtest/gtest.h>

#include "core/files.h"
#include "core/volume_io.h"
#include "synthetic_scene.h"
#include "needs_two_cores.h"

namespace voltree {
namespace {

TEST(Determinism, SameBytesForOneAndTwoThreads) {
  VOLTREE_SKIP_UNLESS_TWO_CORES();
  const ReconstructInput input = testing::PhantomInput(testing::BlobPhantom(16), 12, 48);
  ReconstructOptions options;
  options.levels = 5;
  Progress quiet(true);
  testing::TempDir dir("determinism");
  std::string bytes[3];
  for (int run = 0; run < 3; ++run) {
    options.threads = run == 0 ? 1 : 2;
    const Volume volume = Reconstruct(input, options, &quiet);
    const auto folder = dir.path / ("volume" + std::to_string(run));
    WriteVolume(folder, volume, options.ToJson());
    bytes[run] = ReadFile(folder / kVolumeBinName) + ReadFile(folder / kVolumeJsonName);
  }
  EXPECT_GT(bytes[0].size(), 1000u);
  EXPECT_EQ(bytes[0], bytes[1]);
  EXPECT_EQ(bytes[1], bytes[2]);
}

}  // namespace
}  // namespace voltree
