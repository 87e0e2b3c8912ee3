// Matting again the pixels a leaf covers in part, on the studio's young oak in front of the
// realistic backdrop (sky, hills and tree lines behind the lower ring's crowns, ground behind the
// upper ring's), with mattes that made every such pixel whole.
#include "capture/matte/mixed_pixels.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <string>

#include "capture/matte/cv.h"
#include "capture/matte/metrics.h"
#include "capture/matte/sky_estimate.h"
#include "capture/young_oak_photos.h"
#include "core/error.h"
#include "expect_check_names.h"

namespace voltree {
namespace {

// The truth with every pixel the tree touches made whole: what a matte gives that finds every
// leaf and none of their edges.
Image8 Whole(const Image8& truth) {
  Image8 matte = truth;
  for (uint8_t& alpha : matte.pixels) alpha = alpha > 0 ? 255 : 0;
  return matte;
}

// Measured at 192², 16 photos: matte MSE 0.0149 whole, 0.0109 solved (0.73 times); every opaque
// pixel of the truth kept whole.
TEST(MatteMixedPixels, SolvesTheLeavesAWholeMatteMadeWhole) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("");
  ASSERT_FALSE(set.views.empty());
  double whole_mse = 0, mixed_mse = 0, opaque = 0, opaque_kept = 0;
  for (size_t i = 0; i < set.views.size(); ++i) {
    const Image8 whole = Whole(set.truth[i]);
    const Image8 mixed = MatteMixedPixels(set.photos[i], whole, MatteOptions{}, MixedPixelOptions{});
    whole_mse += CompareMattes(whole, set.truth[i]).mse / 1000;
    mixed_mse += CompareMattes(mixed, set.truth[i]).mse / 1000;
    for (size_t p = 0; p < mixed.pixels.size(); ++p)
      if (set.truth[i].pixels[p] == 255) {
        ++opaque;
        opaque_kept += mixed.pixels[p] / 255.0;
      }
  }
  whole_mse /= double(set.views.size());
  mixed_mse /= double(set.views.size());
  std::printf("matte MSE %.5f whole, %.5f mixed pixels solved; alpha kept on opaque pixels %.3f\n", whole_mse,
              mixed_mse, opaque_kept / opaque);
  EXPECT_LT(mixed_mse, 0.85 * whole_mse);
  EXPECT_GT(opaque_kept / opaque, 0.97);
}

// A first matte that took a patch of clear sky left of the crown for the tree. The solver clears
// most of it either way; the clear sky (sky_estimate.h) is known background unless the pass is
// given no clear sky, as the hull's re-check does when its `keep_clear_sky` is off.
// Measured on the first eye-level photo at 192²: no clear-sky pixel above zero kept, 6 (alpha
// 1.1 in all) left to the solver.
TEST(MatteMixedPixels, KeepsTheClearSkyBackgroundOnlyWhenAsked) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("");
  ASSERT_FALSE(set.views.empty());
  Image8 matte = Whole(set.truth[0]);
  for (int y = 30; y < 46; ++y)
    for (int x = 30; x < 46; ++x) matte.at(x, y) = 255;
  const matte::SkyEstimate sky = matte::EstimatePhotoSky(matte::View(set.photos[0]), MatteOptions{});
  const cv::Mat clear_sky = sky.ClearSky();
  ASSERT_GT(cv::countNonZero(clear_sky), 0);
  const Image8 known_sky = matte::ToImage8(clear_sky);
  auto clear_sky_with_alpha = [&](bool keep_clear_sky) {
    const Image8 mixed = MatteMixedPixels(set.photos[0], matte, sky, keep_clear_sky ? &known_sky : nullptr, nullptr,
                                          MatteOptions{}, MixedPixelOptions{});
    return cv::countNonZero(clear_sky & (matte::View(mixed) > 0));
  };
  const int kept = clear_sky_with_alpha(true), solved = clear_sky_with_alpha(false);
  std::printf("clear-sky pixels above zero: %d kept, %d left to the solver\n", kept, solved);
  EXPECT_EQ(kept, 0);
  EXPECT_GT(solved, 0);
}

TEST(MixedPixelOptions, CheckNamesTheField) {
  MixedPixelOptions options;
  options.pure = 0;
  testing::ExpectCheckNames(options, "MixedPixelOptions.pure");
}

}  // namespace
}  // namespace voltree
