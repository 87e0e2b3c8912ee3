#include "core/image_metrics.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numeric>

#include "core/error.h"

namespace voltree {
namespace {

void CheckSameShape(const ImageF& a, const ImageF& b, const char* what) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    Fail(what, ": images differ in shape (", a.width, "x", a.height, "x", a.channels, " vs ", b.width, "x", b.height,
         "x", b.channels, ")");
}

// Sums per row in parallel, then adds the rows in order, so the total is the same bit for bit
// whatever the thread count.
template <typename RowSum>
double DeterministicSum(int rows, RowSum row_sum) {
  std::vector<double> sums(size_t(std::max(rows, 0)), 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y) sums[size_t(y)] = row_sum(y);
  });
  return std::accumulate(sums.begin(), sums.end(), 0.0);
}

std::vector<double> GaussianKernel(int size, double sigma) {
  std::vector<double> kernel(size_t(size), 0.0);
  const double centre = 0.5 * (size - 1);
  double total = 0;
  for (int i = 0; i < size; ++i) {
    const double d = i - centre;
    kernel[size_t(i)] = std::exp(-d * d / (2 * sigma * sigma));
    total += kernel[size_t(i)];
  }
  for (double& k : kernel) k /= total;
  return kernel;
}

// Mean SSIM of one channel over the valid region (Wang et al. 2004, eq. 13 and 15).
double ChannelSsim(const ImageF& a, const ImageF& b, int channel, const std::vector<double>& kernel, double peak) {
  const int window = int(kernel.size());
  const int out_w = a.width - window + 1;
  const int out_h = a.height - window + 1;
  // Horizontal pass of the five moments: mu_a, mu_b, E[a^2], E[b^2], E[ab].
  constexpr int kMoments = 5;
  std::vector<double> rows(size_t(out_w) * a.height * kMoments);
  tbb::parallel_for(0, a.height, [&](int y) {
    for (int x = 0; x < out_w; ++x) {
      double m[kMoments] = {0, 0, 0, 0, 0};
      for (int k = 0; k < window; ++k) {
        const double va = a.at(x + k, y, channel), vb = b.at(x + k, y, channel), w = kernel[size_t(k)];
        m[0] += w * va;
        m[1] += w * vb;
        m[2] += w * va * va;
        m[3] += w * vb * vb;
        m[4] += w * va * vb;
      }
      for (int i = 0; i < kMoments; ++i) rows[(size_t(y) * out_w + x) * kMoments + i] = m[i];
    }
  });
  const double c1 = (0.01 * peak) * (0.01 * peak);
  const double c2 = (0.03 * peak) * (0.03 * peak);
  const double total = DeterministicSum(out_h, [&](int y) {
    double row_total = 0;
    for (int x = 0; x < out_w; ++x) {
      double m[kMoments] = {0, 0, 0, 0, 0};
      for (int k = 0; k < window; ++k)
        for (int i = 0; i < kMoments; ++i) m[i] += kernel[size_t(k)] * rows[(size_t(y + k) * out_w + x) * kMoments + i];
      const double var_a = m[2] - m[0] * m[0];
      const double var_b = m[3] - m[1] * m[1];
      const double cov = m[4] - m[0] * m[1];
      row_total +=
          ((2 * m[0] * m[1] + c1) * (2 * cov + c2)) / ((m[0] * m[0] + m[1] * m[1] + c1) * (var_a + var_b + c2));
    }
    return row_total;
  });
  return total / (double(out_w) * out_h);
}

// Halves an image by averaging 2x2 blocks; an odd last row or column is dropped.
ImageF HalveBox(const ImageF& image) {
  ImageF half(image.width / 2, image.height / 2, image.channels);
  tbb::parallel_for(0, half.height, [&](int y) {
    for (int x = 0; x < half.width; ++x)
      for (int c = 0; c < image.channels; ++c)
        half.at(x, y, c) = 0.25f * (image.at(2 * x, 2 * y, c) + image.at(2 * x + 1, 2 * y, c) +
                                    image.at(2 * x, 2 * y + 1, c) + image.at(2 * x + 1, 2 * y + 1, c));
  });
  return half;
}

double RootMeanSquare(const ImageF& image) {
  const size_t row_size = size_t(image.width) * image.channels;
  const double sum = DeterministicSum(image.height, [&](int y) {
    double s = 0;
    for (size_t i = 0; i < row_size; ++i) {
      const double v = image.pixels[size_t(y) * row_size + i];
      s += v * v;
    }
    return s;
  });
  return std::sqrt(sum / double(image.pixels.size()));
}

void CheckRgbaPair(const Image8& render, const Image8& truth) {
  if (render.channels != 4) Fail("image metrics: the render has ", render.channels, " channels, expected RGBA (4)");
  if (truth.channels != 4) Fail("image metrics: the truth has ", truth.channels, " channels, expected RGBA (4)");
  if (render.width != truth.width || render.height != truth.height)
    Fail("image metrics: the render is ", render.width, "x", render.height, " but the truth is ", truth.width, "x",
         truth.height, "; expected the same size");
  if (render.empty()) Fail("image metrics: the images are empty");
}

}  // namespace

void ImageMetricsOptions::Check() const {
  if (!(background_grey >= 0 && background_grey <= 255))
    FailOption("ImageMetricsOptions.background_grey", "must be in 0..255, got ", background_grey);
  if (!(coverage_threshold >= 0 && coverage_threshold < 1))
    Fail("image metrics option coverage_threshold = ", coverage_threshold, ", expected 0 <= t < 1");
  if (ssim_window < 3 || ssim_window % 2 == 0)
    Fail("image metrics option ssim_window = ", ssim_window, ", expected an odd size >= 3");
  if (!(ssim_sigma > 0)) Fail("image metrics option ssim_sigma = ", ssim_sigma, ", expected > 0");
  if (max_rms_scales < 0) Fail("image metrics option max_rms_scales = ", max_rms_scales, ", expected >= 0");
}

double CoverageCounts::Precision() const {
  const int64_t set = true_positives + false_positives;
  return set == 0 ? 1.0 : double(true_positives) / double(set);
}

double CoverageCounts::Recall() const {
  const int64_t relevant = true_positives + false_negatives;
  return relevant == 0 ? 1.0 : double(true_positives) / double(relevant);
}

ImageF CompositeOverGrey(const Image8& rgba, float grey, bool premultiplied) {
  if (rgba.channels != 4) Fail("CompositeOverGrey: expected RGBA, got ", rgba.channels, " channels");
  ImageF out(rgba.width, rgba.height, 3);
  const size_t count = size_t(rgba.width) * rgba.height;
  for (size_t i = 0; i < count; ++i) {
    const float alpha = rgba.pixels[i * 4 + 3] / 255.0f;
    for (int c = 0; c < 3; ++c) {
      const float colour = rgba.pixels[i * 4 + size_t(c)];
      out.pixels[i * 3 + size_t(c)] = (premultiplied ? colour : alpha * colour) + (1.0f - alpha) * grey;
    }
  }
  return out;
}

ImageF ExtractChannel(const Image8& image, int channel) {
  if (channel < 0 || channel >= image.channels)
    Fail("ExtractChannel: channel ", channel, " of an image with ", image.channels, " channels");
  ImageF out(image.width, image.height, 1);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = image.pixels[i * size_t(image.channels) + size_t(channel)];
  return out;
}

double MeanSquaredError(const ImageF& a, const ImageF& b) {
  CheckSameShape(a, b, "MeanSquaredError");
  if (a.empty()) Fail("MeanSquaredError: the images are empty");
  const size_t row_size = size_t(a.width) * a.channels;
  const double sum = DeterministicSum(a.height, [&](int y) {
    double s = 0;
    for (size_t i = size_t(y) * row_size; i < size_t(y + 1) * row_size; ++i) {
      const double d = double(a.pixels[i]) - double(b.pixels[i]);
      s += d * d;
    }
    return s;
  });
  return sum / double(a.pixels.size());
}

double PsnrFromMse(double mse, double peak) {
  if (mse <= 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

double StructuralSimilarity(const ImageF& a, const ImageF& b, int window, double sigma, double peak) {
  CheckSameShape(a, b, "StructuralSimilarity");
  if (a.width < window || a.height < window)
    Fail("SSIM: the images are ", a.width, "x", a.height, ", expected at least the window, ", window, "x", window);
  const std::vector<double> kernel = GaussianKernel(window, sigma);
  double total = 0;
  for (int c = 0; c < a.channels; ++c) total += ChannelSsim(a, b, c, kernel, peak);
  return total / a.channels;
}

CoverageCounts CountCoverage(const Image8& render, const Image8& truth, float threshold) {
  CheckRgbaPair(render, truth);
  CoverageCounts counts;
  const size_t count = size_t(render.width) * render.height;
  for (size_t i = 0; i < count; ++i) {
    const bool in_render = render.pixels[i * 4 + 3] / 255.0f > threshold;
    const bool in_truth = truth.pixels[i * 4 + 3] / 255.0f > threshold;
    counts.true_positives += in_render && in_truth;
    counts.false_positives += in_render && !in_truth;
    counts.false_negatives += !in_render && in_truth;
  }
  return counts;
}

std::vector<double> PyramidRms(const ImageF& difference, int max_scales) {
  if (difference.empty()) Fail("PyramidRms: the image is empty");
  std::vector<double> rms;
  ImageF level = difference;
  while (true) {
    rms.push_back(RootMeanSquare(level));
    if (max_scales > 0 && int(rms.size()) >= max_scales) break;
    if (level.width < 2 || level.height < 2) break;
    level = HalveBox(level);
  }
  return rms;
}

ViewMetrics CompareViews(const Image8& render, const Image8& truth, const ImageMetricsOptions& options) {
  options.Check();
  CheckRgbaPair(render, truth);
  ViewMetrics metrics;
  const ImageF render_rgb = CompositeOverGrey(render, options.background_grey, options.render_premultiplied);
  const ImageF truth_rgb = CompositeOverGrey(truth, options.background_grey, options.truth_premultiplied);
  metrics.rgb_psnr = PsnrFromMse(MeanSquaredError(render_rgb, truth_rgb), 255.0);
  metrics.rgb_ssim = StructuralSimilarity(render_rgb, truth_rgb, options.ssim_window, options.ssim_sigma, 255.0);
  metrics.alpha_psnr = PsnrFromMse(MeanSquaredError(ExtractChannel(render, 3), ExtractChannel(truth, 3)), 255.0);
  metrics.coverage = CountCoverage(render, truth, options.coverage_threshold);
  metrics.precision = metrics.coverage.Precision();
  metrics.recall = metrics.coverage.Recall();

  ImageF difference(render_rgb.width, render_rgb.height, 3);
  for (size_t i = 0; i < difference.pixels.size(); ++i)
    difference.pixels[i] = (render_rgb.pixels[i] - truth_rgb.pixels[i]) / 255.0f;
  metrics.rms_per_scale = PyramidRms(difference, options.max_rms_scales);
  metrics.multiscale_rms = std::accumulate(metrics.rms_per_scale.begin(), metrics.rms_per_scale.end(), 0.0) /
                           double(metrics.rms_per_scale.size());
  return metrics;
}

}  // namespace voltree
