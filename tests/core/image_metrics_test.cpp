// Image metrics on images whose metrics are known in closed form.
#include "core/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"

namespace voltree {
namespace {

// Opaque-ish RGBA pattern with colours in 20..219, so offsets of up to +-30 never clip.
Image8 Pattern(int width, int height, uint8_t alpha = 255) {
  Image8 image(width, height, 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = uint8_t(20 + (x * 37 + y * 11 + c * 91) % 200);
      image.at(x, y, 3) = alpha;
    }
  return image;
}

Image8 AddToColour(Image8 image, int offset) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = uint8_t(image.at(x, y, c) + offset);
  return image;
}

// Opaque rectangle [x0, x0 + w) x [y0, y0 + h) on a transparent image.
Image8 Rectangle(int width, int height, int x0, int y0, int w, int h) {
  Image8 image(width, height, 4);
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x)
      for (int c = 0; c < 4; ++c) image.at(x, y, c) = c == 3 ? 255 : 90;
  return image;
}

// Reference values computed outside this code base (a plain Python script that builds the 2-D
// 11x11 Gaussian window directly, not separably, and follows Wang et al.'s reference formulas and
// the RMS pyramid as defined in the header) for a pattern and a deterministic perturbation of
// +-10 levels. The test compares the code with these numbers, not with its own arithmetic.
TEST(ImageMetrics, MatchesIndependentlyComputedReferenceValues) {
  const Image8 truth = Pattern(32, 24);
  Image8 render = truth;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) render.at(x, y, c) = uint8_t(render.at(x, y, c) + (x * 7 + y * 13 + c * 5) % 21 - 10);
  const ViewMetrics m = CompareViews(render, truth);
  EXPECT_NEAR(m.rgb_psnr, 32.495034930540, 1e-6);
  EXPECT_NEAR(m.rgb_ssim, 0.994342112743, 1e-6);
  const double rms[] = {0.023727296291, 0.008576388646, 0.004200023867, 0.000979913333, 0.000458067091};
  ASSERT_EQ(m.rms_per_scale.size(), 5u);
  for (size_t i = 0; i < 5; ++i) EXPECT_NEAR(m.rms_per_scale[i], rms[i], 1e-7) << "scale " << i;
  EXPECT_NEAR(m.multiscale_rms, 0.007588337846, 1e-7);
  // Literal values, not formulas: 20 log10(255 / 10) and 20 log10(255 / 6).
  EXPECT_NEAR(CompareViews(AddToColour(truth, 10), truth).rgb_psnr, 28.130803608679, 1e-9);
  EXPECT_NEAR(PsnrFromMse(36.0, 255.0), 32.567778601006, 1e-9);
}

TEST(ImageMetrics, IdenticalImagesArePerfect) {
  Image8 truth = Pattern(32, 24);
  for (int x = 0; x < 32; ++x) truth.at(x, 5, 3) = uint8_t(x * 8);  // some fractional alpha too
  const ViewMetrics m = CompareViews(truth, truth);
  EXPECT_TRUE(std::isinf(m.rgb_psnr) && m.rgb_psnr > 0);
  EXPECT_TRUE(std::isinf(m.alpha_psnr) && m.alpha_psnr > 0);
  EXPECT_EQ(m.rgb_ssim, 1.0);  // numerator and denominator are computed from the same numbers
  EXPECT_EQ(m.precision, 1.0);
  EXPECT_EQ(m.recall, 1.0);
  EXPECT_EQ(m.coverage.false_positives + m.coverage.false_negatives, 0);
  EXPECT_EQ(m.multiscale_rms, 0.0);
  // 32x24 -> 16x12 -> 8x6 -> 4x3 -> 2x1: floor(log2(24)) + 1 levels.
  ASSERT_EQ(m.rms_per_scale.size(), 5u);
  for (double rms : m.rms_per_scale) EXPECT_EQ(rms, 0.0);
}

TEST(ImageMetrics, ConstantColourOffsetGivesAnalyticPsnrAndRms) {
  const Image8 truth = Pattern(32, 24);
  const ViewMetrics m = CompareViews(AddToColour(truth, 10), truth);
  // MSE = 10^2, so PSNR = 20 log10(255 / 10) = 28.1308 dB.
  EXPECT_NEAR(m.rgb_psnr, 20 * std::log10(255.0 / 10.0), 1e-9);
  EXPECT_TRUE(std::isinf(m.alpha_psnr));
  // A constant offset survives every box-filter level unchanged: 10/255 at every scale.
  for (double rms : m.rms_per_scale) EXPECT_NEAR(rms, 10.0 / 255.0, 1e-6);
  EXPECT_NEAR(m.multiscale_rms, 10.0 / 255.0, 1e-6);
  EXPECT_LT(m.rgb_ssim, 1.0);
}

TEST(ImageMetrics, CheckerboardNoiseVanishesAtCoarseScales) {
  const Image8 truth = Pattern(32, 32);
  Image8 render = truth;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) render.at(x, y, c) = uint8_t(render.at(x, y, c) + ((x + y) % 2 ? 6 : -6));
  const ViewMetrics m = CompareViews(render, truth);
  EXPECT_NEAR(m.rgb_psnr, 20 * std::log10(255.0 / 6.0), 1e-9);  // MSE = 36
  ASSERT_EQ(m.rms_per_scale.size(), 6u);                        // 32, 16, 8, 4, 2, 1
  EXPECT_NEAR(m.rms_per_scale[0], 6.0 / 255.0, 1e-6);
  for (size_t i = 1; i < m.rms_per_scale.size(); ++i) EXPECT_NEAR(m.rms_per_scale[i], 0.0, 1e-7) << i;
  EXPECT_NEAR(m.multiscale_rms, 6.0 / 255.0 / 6.0, 1e-6);
}

TEST(ImageMetrics, AlphaOffsetGivesAnalyticAlphaPsnr) {
  const ViewMetrics m = CompareViews(Pattern(16, 16, 190), Pattern(16, 16, 200));
  EXPECT_NEAR(m.alpha_psnr, 20 * std::log10(255.0 / 10.0), 1e-9);
  // Both alphas are above 0.5: coverage agrees exactly.
  EXPECT_EQ(m.precision, 1.0);
  EXPECT_EQ(m.recall, 1.0);
}

TEST(ImageMetrics, SsimOfConstantImagesMatchesTheFormula) {
  // Constant images: variances and covariance are 0, so SSIM = (2ab + C1) / (a^2 + b^2 + C1).
  const double a = 100, b = 110, c1 = (0.01 * 255) * (0.01 * 255);
  ImageF image_a(20, 15, 1, float(a)), image_b(20, 15, 1, float(b));
  EXPECT_NEAR(StructuralSimilarity(image_a, image_b, 11, 1.5, 255), (2 * a * b + c1) / (a * a + b * b + c1), 1e-9);
}

TEST(ImageMetrics, SsimOfCheckerboardContrastChangeMatchesTheFormula) {
  // a = 100 + 10 s, b = 100 + 20 s with s = +-1 in a checkerboard. In a window of the separable
  // Gaussian w, E[s] = +-g^2 with g = sum_k w_k (-1)^k (sign by window parity) and E[s^2] = 1, so
  // mu_a = 100 + 10 E[s], var_a = 100 (1 - g^4), var_b = 4 var_a, cov = 2 var_a in every window.
  ImageF a(24, 24, 1), b(24, 24, 1);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      const float s = (x + y) % 2 ? 1.0f : -1.0f;
      a.at(x, y) = 100 + 10 * s;
      b.at(x, y) = 100 + 20 * s;
    }
  double g = 0, total = 0;
  for (int k = 0; k < 11; ++k) {
    const double w = std::exp(-(k - 5.0) * (k - 5.0) / (2 * 1.5 * 1.5));
    g += (k % 2 ? -w : w);
    total += w;
  }
  g /= total;
  const double c1 = 2.55 * 2.55, c2 = 7.65 * 7.65, var = 1 - g * g * g * g;
  auto ssim = [&](double mean_s) {
    const double mu_a = 100 + 10 * mean_s, mu_b = 100 + 20 * mean_s;
    return (2 * mu_a * mu_b + c1) * (2 * 200 * var + c2) / ((mu_a * mu_a + mu_b * mu_b + c1) * (500 * var + c2));
  };
  // 14x14 valid windows, half of each parity.
  const double expected = 0.5 * (ssim(g * g) + ssim(-g * g));
  EXPECT_NEAR(StructuralSimilarity(a, b, 11, 1.5, 255), expected, 1e-9);
  EXPECT_NEAR(expected, 0.8217, 1e-3);  // contrast doubled, structure intact: well below 1
}

TEST(ImageMetrics, OnePixelShiftGivesAnalyticPrecisionAndRecall) {
  // A 10x6 rectangle moved right by one pixel: tp = 9*6, fp = 6, fn = 6, so P = R = 0.9.
  const Image8 truth = Rectangle(24, 16, 5, 4, 10, 6);
  const Image8 render = Rectangle(24, 16, 6, 4, 10, 6);
  const ViewMetrics m = CompareViews(render, truth);
  EXPECT_EQ(m.coverage.true_positives, 54);
  EXPECT_EQ(m.coverage.false_positives, 6);
  EXPECT_EQ(m.coverage.false_negatives, 6);
  EXPECT_DOUBLE_EQ(m.precision, 0.9);
  EXPECT_DOUBLE_EQ(m.recall, 0.9);
  // A render that is the truth minus its last column: P = 1 (nothing wrong set), R = 9/10.
  const ViewMetrics pruned = CompareViews(Rectangle(24, 16, 5, 4, 9, 6), truth);
  EXPECT_DOUBLE_EQ(pruned.precision, 1.0);
  EXPECT_DOUBLE_EQ(pruned.recall, 0.9);
}

TEST(ImageMetrics, CoverageThresholdIsStrict) {
  Image8 truth(4, 1, 4), render(4, 1, 4);
  const uint8_t alphas[4] = {0, 1, 127, 128};  // 128/255 > 0.5 >= 127/255
  for (int x = 0; x < 4; ++x) render.at(x, 0, 3) = alphas[x];
  truth.at(0, 0, 3) = truth.at(1, 0, 3) = truth.at(2, 0, 3) = truth.at(3, 0, 3) = 255;
  EXPECT_EQ(CountCoverage(render, truth, 0.5f).true_positives, 1);
  EXPECT_EQ(CountCoverage(render, truth, 0.0f).true_positives, 3);
}

TEST(ImageMetrics, EmptyCoverageCountsAsPerfectPrecisionOrRecall) {
  const Image8 empty(8, 8, 4);
  const CoverageCounts nothing_rendered = CountCoverage(empty, Rectangle(8, 8, 1, 1, 2, 2), 0.5f);
  EXPECT_EQ(nothing_rendered.Precision(), 1.0);
  EXPECT_EQ(nothing_rendered.Recall(), 0.0);
  const CoverageCounts nothing_true = CountCoverage(Rectangle(8, 8, 1, 1, 2, 2), empty, 0.5f);
  EXPECT_EQ(nothing_true.Precision(), 0.0);
  EXPECT_EQ(nothing_true.Recall(), 1.0);
}

TEST(ImageMetrics, MoreNoiseIsWorseOnEveryMetric) {
  const Image8 truth = Pattern(48, 40);
  std::mt19937 random(7);
  ViewMetrics previous = CompareViews(truth, truth);
  for (int amplitude : {2, 5, 10, 20}) {
    Image8 render = truth;
    std::uniform_int_distribution<int> noise(-amplitude, amplitude);
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 48; ++x)
        for (int c = 0; c < 3; ++c) render.at(x, y, c) = uint8_t(render.at(x, y, c) + noise(random));
    const ViewMetrics m = CompareViews(render, truth);
    EXPECT_LT(m.rgb_psnr, previous.rgb_psnr) << amplitude;
    EXPECT_LT(m.rgb_ssim, previous.rgb_ssim) << amplitude;
    EXPECT_GT(m.multiscale_rms, previous.multiscale_rms) << amplitude;
    previous = m;
  }
}

TEST(ImageMetrics, CompositeOverGreyHandlesStraightAndPremultipliedAlpha) {
  Image8 straight(3, 1, 4), premultiplied(3, 1, 4);
  // transparent, half, opaque pixels of colour 200
  const uint8_t alphas[3] = {0, 51, 255};
  for (int x = 0; x < 3; ++x) {
    straight.at(x, 0, 0) = straight.at(x, 0, 1) = straight.at(x, 0, 2) = 200;
    straight.at(x, 0, 3) = premultiplied.at(x, 0, 3) = alphas[x];
    premultiplied.at(x, 0, 0) = premultiplied.at(x, 0, 1) = premultiplied.at(x, 0, 2) = uint8_t(200 * alphas[x] / 255);
  }
  const ImageF a = CompositeOverGrey(straight, 128, false);
  const ImageF b = CompositeOverGrey(premultiplied, 128, true);
  EXPECT_FLOAT_EQ(a.at(0, 0), 128.0f);
  EXPECT_FLOAT_EQ(a.at(1, 0), 0.2f * 200 + 0.8f * 128);
  EXPECT_FLOAT_EQ(a.at(2, 0), 200.0f);
  for (int x = 0; x < 3; ++x) EXPECT_FLOAT_EQ(a.at(x, 0), b.at(x, 0)) << x;
}

TEST(ImageMetrics, RejectsMismatchedInputsAndBadOptions) {
  EXPECT_THROW(CompareViews(Pattern(8, 8), Pattern(9, 8)), Error);
  EXPECT_THROW(CompareViews(Image8(16, 16, 3), Pattern(16, 16)), Error);
  EXPECT_THROW(CompareViews(Pattern(8, 8), Pattern(8, 8)), Error);  // smaller than the SSIM window
  ImageMetricsOptions options;
  options.ssim_window = 10;
  EXPECT_THROW(options.Check(), Error);
  options = {};
  options.coverage_threshold = 1.0f;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_NO_THROW(ImageMetricsOptions{}.Check());
}

}  // namespace
}  // namespace voltree
