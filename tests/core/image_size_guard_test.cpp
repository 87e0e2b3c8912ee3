// The decompression-bomb guard: declared sizes are checked before any pixel is decoded.
#include "core/image_size_guard.h"

#include <gtest/gtest.h>

namespace voltree {
namespace {

TEST(ImageSizeGuard, AcceptsCameraSizedPhotos) {
  EXPECT_FALSE(ImageSizeProblem(6000, 4000, 3, 1, std::nullopt));
  EXPECT_FALSE(ImageSizeProblem(16384, 16384, 4, 1, std::nullopt));  // exactly the cap
  EXPECT_FALSE(ImageSizeProblem(4000, 3000, 4, 4, int64_t(1) << 30));
}

TEST(ImageSizeGuard, RefusesDeclaredSizesAboveTheCap) {
  const auto problem = ImageSizeProblem(60000, 60000, 3, 1, std::nullopt);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("60000x60000"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("16384x16384"), std::string::npos) << *problem;
  EXPECT_TRUE(ImageSizeProblem(16385, 16384, 1, 1, std::nullopt));
  // Sizes whose product overflows 64 bits are refused, not wrapped around.
  EXPECT_TRUE(ImageSizeProblem(int64_t(1) << 40, int64_t(1) << 40, 4, 4, std::nullopt));
  EXPECT_TRUE(ImageSizeProblem(0, 10, 3, 1, std::nullopt));
}

TEST(ImageSizeGuard, RefusesWhatTheFreeMemoryCannotHold) {
  // 8000 x 8000 RGBA floats: 2 x 1 GB to decode; 512 MiB free is not enough.
  const auto problem = ImageSizeProblem(8000, 8000, 4, 4, int64_t(512) << 20);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("512 MiB"), std::string::npos) << *problem;
  EXPECT_EQ(DecodeBytes(8000, 8000, 4, 4), 2 * int64_t(8000) * 8000 * 16);
}

TEST(ImageSizeGuard, KnowsTheFreeMemoryOnLinux) {
  const auto available = FreeMemoryBytes();
  ASSERT_TRUE(available);
  EXPECT_GT(*available, 0);
}

}  // namespace
}  // namespace voltree
