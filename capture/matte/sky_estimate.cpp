#include "capture/matte/sky_estimate.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace voltree::matte {

namespace {

// Bright, nearly grey pixels: clouds and overcast sky that the smooth model cannot follow.
cv::Mat CloudMask(const cv::Mat& lab) {
  cv::Mat mask(lab.size(), CV_8U);
  for (int y = 0; y < lab.rows; ++y)
    for (int x = 0; x < lab.cols; ++x) {
      const cv::Vec3f p = lab.at<cv::Vec3f>(y, x);
      mask.at<uint8_t>(y, x) = p[0] > 82.0f && std::hypot(p[1], p[2]) < 10.0f ? 255 : 0;
    }
  return mask;
}

}  // namespace

cv::Mat RowsAbove(int rows, int cols, int horizon) {
  cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8U);
  if (horizon > 0) mask.rowRange(0, std::min(horizon, rows)).setTo(255);
  return mask;
}

int EstimateHorizonRow(const cv::Mat& sky_mask, double min_fraction) {
  // Relative to the sky-richest row as well: hazy distant ground just above the horizon matches
  // the sky in a few pixels per row, the sky rows (even behind the crown) in many.
  int richest = 0;
  for (int y = 0; y < sky_mask.rows; ++y) richest = std::max(richest, cv::countNonZero(sky_mask.row(y)));
  const int needed = std::max({1, int(std::ceil(min_fraction * sky_mask.cols)), richest / 5});
  for (int y = sky_mask.rows - 1; y >= 0; --y)
    if (cv::countNonZero(sky_mask.row(y)) >= needed) return y + 1;
  return 0;
}

double SkyEstimate::Tolerance(const MatteOptions& options) const {
  return std::max(options.sky_tolerance, 3.0 * model.sigma);
}

int SkyEstimate::MixedRowsStart() const {
  const int margin = std::max(4, pixels.rows / 100);
  return horizon < pixels.rows ? std::max(0, horizon - margin) : horizon;
}

cv::Mat SkyEstimate::ClearSky() const {
  if (!model.valid()) return cv::Mat::zeros(pixels.size(), CV_8U);
  return pixels & ~clouds & RowsAbove(pixels.rows, pixels.cols, MixedRowsStart());
}

SkyEstimate EstimateSky(const cv::Mat& lab, const MatteOptions& options) {
  CV_Assert(lab.type() == CV_32FC3);
  const int rows = lab.rows, cols = lab.cols;
  SkyEstimate sky;
  const int seed_rows = std::clamp(int(std::lround(options.sky_seed_rows * rows)), 1, rows);
  sky.model = FitSkyModel(lab, RowsAbove(rows, cols, seed_rows));
  // Sky is smooth; textured ground in the top rows (a camera looking down) is not.
  if (sky.model.valid() && sky.model.sigma > options.max_sky_sigma && options.horizon < 0) sky.model = SkyModel{};
  sky.clouds = options.clouds ? CloudMask(lab) : cv::Mat::zeros(lab.size(), CV_8U);
  auto explained = [&] {
    if (!sky.model.valid()) return sky.clouds.clone();
    const cv::Mat mask = SkyDistance(lab, sky.model) < sky.Tolerance(options);
    return cv::Mat(mask | sky.clouds);
  };
  sky.pixels = explained();
  sky.horizon = options.horizon >= 0 ? int(std::lround(options.horizon * rows))
                : sky.model.valid()  ? EstimateHorizonRow(sky.pixels)
                                     : 0;
  for (int round = 0; round < 2 && sky.horizon > 0; ++round) {
    const SkyModel refit = FitSkyModel(lab, sky.pixels & ~sky.clouds & RowsAbove(rows, cols, sky.horizon));
    if (!refit.valid()) break;
    sky.model = refit;
    sky.pixels = explained();
    if (options.horizon < 0) sky.horizon = EstimateHorizonRow(sky.pixels);
  }
  return sky;
}

SkyEstimate EstimatePhotoSky(const cv::Mat& rgb8, const MatteOptions& options) {
  CV_Assert(rgb8.type() == CV_8UC3);
  cv::Mat lab;
  rgb8.convertTo(lab, CV_32F, 1.0 / 255.0);
  cv::cvtColor(lab, lab, cv::COLOR_RGB2Lab);
  return EstimateSky(lab, options);
}

}  // namespace voltree::matte
