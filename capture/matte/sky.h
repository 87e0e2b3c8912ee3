// Internal: the sky colour model. Sky is smooth: a quadratic in image position per CIELab
// channel, fitted robustly to the top rows and then to every pixel it explains, captures the
// vertical gradient and sun-side brightening. Pixels far from it are tree (or ground).
#pragma once

#include <array>

#include <opencv2/core.hpp>

namespace voltree::matte {

struct SkyModel {
  // Lab channel c at normalized position (u, v) in [-1, 1]^2:
  // sum_k coefficients[c][k] * {1, u, v, u^2, u v, v^2}[k].
  std::array<std::array<double, 6>, 3> coefficients{};
  double sigma = 0.0;  // robust spread of the sky samples around the model (Lab units)
  int samples = 0;     // 0: no sky was found

  bool valid() const { return samples > 0; }
  // CV_32FC3 Lab image of the model over a width x height image.
  cv::Mat Predict(cv::Size size) const;
};

// Fits the model to the pixels of `lab` (CV_32FC3) where `mask` (CV_8U) is non-zero, with
// iteratively trimmed least squares; subsamples to at most `max_samples` pixels, deterministically.
SkyModel FitSkyModel(const cv::Mat& lab, const cv::Mat& mask, int max_samples = 40000);

// Per-pixel Lab distance (CV_32F) between `lab` and the model.
cv::Mat SkyDistance(const cv::Mat& lab, const SkyModel& model);

}  // namespace voltree::matte
