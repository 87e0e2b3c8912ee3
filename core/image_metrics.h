// Image-quality metrics that compare a render of the asset with the truth, one view at a time:
// RGB PSNR and SSIM over a fixed grey background, alpha PSNR, precision and recall of covered
// pixels (Neubert et al. 2011) and multi-scale RMS error (Clasen et al. 2011).
//
// Inputs are 8-bit RGBA images of the same size. Alpha is STRAIGHT by default (Image8 as
// ReadImage8 returns it); set the *_premultiplied options for premultiplied inputs such as the
// studio's foreground/ and truth/rgba/ images, which are then composited without dividing.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/image.h"

namespace voltree {

struct ImageMetricsOptions {
  // Both images are composited over this grey (8-bit units) before RGB PSNR, SSIM and RMS, so
  // coverage errors count as colour errors against a known, neutral background.
  float background_grey = 128.0f;
  // Neubert et al. count a pixel as covered when geometry is rendered into it. Our renders have
  // fractional alpha, so "rendered" means alpha > threshold (alpha in [0,1]); 0.5 is what an
  // alpha-tested (non-antialiased) rasterization of the same coverage would set.
  float coverage_threshold = 0.5f;
  // SSIM as Wang et al. 2004: Gaussian window 11x11, sigma 1.5, K1 0.01, K2 0.03, L 255.
  int ssim_window = 11;
  double ssim_sigma = 1.5;
  // Multi-scale RMS: how many pyramid levels at most; 0 = down to one pixel on the short side.
  int max_rms_scales = 0;
  bool render_premultiplied = false;
  bool truth_premultiplied = false;

  void Check() const;  // throws Error naming the bad field
};

// Pixel classes of Neubert et al. 2011, table 1 (render = simplified model, truth = original).
struct CoverageCounts {
  int64_t true_positives = 0;   // covered in both
  int64_t false_positives = 0;  // covered only in the render
  int64_t false_negatives = 0;  // covered only in the truth
  // P = tp / (tp + fp); 1 when the render covers nothing (it set no wrong pixel).
  double Precision() const;
  // R = tp / (tp + fn); 1 when the truth covers nothing (nothing was missed).
  double Recall() const;
};

// Metrics of one view. PSNR is +infinity for identical inputs.
struct ViewMetrics {
  double rgb_psnr = 0;    // dB, peak 255, MSE over R, G, B of the composites
  double rgb_ssim = 0;    // mean SSIM of R, G and B of the composites (channels averaged)
  double alpha_psnr = 0;  // dB, peak 255
  CoverageCounts coverage;
  double precision = 0;
  double recall = 0;
  // Root mean square of the signed composite difference (RGB, [0,1] units) at each pyramid
  // level, finest first; each coarser level box-averages 2x2 blocks of the one above.
  std::vector<double> rms_per_scale;
  double multiscale_rms = 0;  // mean of rms_per_scale: every resolution band weighs the same
};

// --- Building blocks, exposed for tests and for other metrics. ---

// RGB composite over a grey background, float in 8-bit units (not rounded, so analytic tests hold).
ImageF CompositeOverGrey(const Image8& rgba, float grey, bool premultiplied);
// One-channel float copy of channel `channel`.
ImageF ExtractChannel(const Image8& image, int channel);
// Mean of squared differences over all samples; the images must have the same shape.
double MeanSquaredError(const ImageF& a, const ImageF& b);
// 10 log10(peak^2 / mse); +infinity when mse is 0.
double PsnrFromMse(double mse, double peak);
// Mean SSIM over the 'valid' region (window fully inside, as Wang's reference code), averaged
// over channels. Throws Error when the image is smaller than the window.
double StructuralSimilarity(const ImageF& a, const ImageF& b, int window, double sigma, double peak);
CoverageCounts CountCoverage(const Image8& render, const Image8& truth, float threshold);
// RMS of `difference` at every level of its 2x2 box pyramid (odd last rows/columns are dropped
// when halving), finest first. `max_scales` 0 = all levels.
std::vector<double> PyramidRms(const ImageF& difference, int max_scales);

// All metrics of one view. Throws Error when the images are not RGBA or differ in size.
ViewMetrics CompareViews(const Image8& render, const Image8& truth, const ImageMetricsOptions& options = {});

}  // namespace voltree
