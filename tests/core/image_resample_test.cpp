// Area resampling: exact means of the covered input area, for integer and fractional ratios, and
// RGBA averaged as premultiplied colour whichever convention it comes in.
#include "core/image_resample.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace voltree {
namespace {

TEST(AreaResample, HalvingAveragesEachTwoByTwoBlock) {
  ImageF in(4, 2, 1);
  for (int x = 0; x < 4; ++x) in.at(x, 0) = float(x), in.at(x, 1) = float(x + 4);
  const ImageF out = AreaResample(in, 2, 1);
  EXPECT_FLOAT_EQ(out.at(0, 0), (0 + 1 + 4 + 5) / 4.0f);
  EXPECT_FLOAT_EQ(out.at(1, 0), (2 + 3 + 6 + 7) / 4.0f);
}

TEST(AreaResample, FractionalRatiosWeighTheCoveredShare) {
  ImageF in(3, 1, 1);
  in.at(0, 0) = 0, in.at(1, 0) = 3, in.at(2, 0) = 6;
  const ImageF out = AreaResample(in, 2, 1);  // each output pixel covers 1.5 input pixels
  EXPECT_FLOAT_EQ(out.at(0, 0), (0 * 1.0f + 3 * 0.5f) / 1.5f);
  EXPECT_FLOAT_EQ(out.at(1, 0), (3 * 0.5f + 6 * 1.0f) / 1.5f);
  // The mean of the image is kept.
  EXPECT_FLOAT_EQ((out.at(0, 0) + out.at(1, 0)) / 2, 3.0f);
  EXPECT_THROW(AreaResample(in, 4, 1), Error);  // only to a smaller size
}

TEST(AreaResample, StraightRgbaIsAveragedAsPremultipliedColour) {
  // A red opaque pixel beside a transparent one whose straight colour is blue: the mean is red at
  // half alpha, not purple.
  Image8 straight(2, 1, 4);
  straight.at(0, 0, 0) = 255, straight.at(0, 0, 3) = 255;
  straight.at(1, 0, 2) = 255, straight.at(1, 0, 3) = 0;
  const Image8 out = AreaResampleRgba(straight, /*premultiplied=*/false, 1, 1);
  EXPECT_EQ(out.at(0, 0, 0), 255);
  EXPECT_EQ(out.at(0, 0, 2), 0);
  EXPECT_EQ(out.at(0, 0, 3), 128);

  Image8 premultiplied = straight;
  premultiplied.at(1, 0, 2) = 0;  // premultiplied by alpha 0
  const Image8 same = AreaResampleRgba(premultiplied, /*premultiplied=*/true, 1, 1);
  EXPECT_EQ(same.at(0, 0, 0), 128);  // premultiplied red at half alpha
  EXPECT_EQ(same.at(0, 0, 3), 128);
}

}  // namespace
}  // namespace voltree
