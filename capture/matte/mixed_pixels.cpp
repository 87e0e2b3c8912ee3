#include "capture/matte/mixed_pixels.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/matte/clean_plate.h"
#include "capture/matte/cv.h"
#include "capture/matte/refine.h"
#include "capture/matte/sky_estimate.h"
#include "core/error.h"

namespace voltree {

void MixedPixelOptions::Check() const {
  if (gap_radius < 1 || gap_radius > 64)
    FailOption("MixedPixelOptions.gap_radius", "must be in [1, 64], got ", gap_radius);
  if (min_gap_pixels < 1) FailOption("MixedPixelOptions.min_gap_pixels", "must be at least 1, got ", min_gap_pixels);
  if (!(min_contrast >= 0)) FailOption("MixedPixelOptions.min_contrast", "must be at least 0, got ", min_contrast);
  if (tree_radius < 1 || tree_radius > 64)
    FailOption("MixedPixelOptions.tree_radius", "must be in [1, 64], got ", tree_radius);
  if (!(pure > 0 && pure <= 1)) FailOption("MixedPixelOptions.pure", "must be in (0, 1], got ", pure);
  if (!(plate_background >= 0 && plate_background < pure))
    FailOption("MixedPixelOptions.plate_background", "must be in [0, pure = ", pure, "), got ", plate_background);
  if (!(plate_match > 0 && plate_match < 1))
    FailOption("MixedPixelOptions.plate_match", "must be in (0, 1), got ", plate_match);
  if (!(plate_line >= 0)) FailOption("MixedPixelOptions.plate_line", "must be at least 0, got ", plate_line);
  if (!(min_plate_spread > 0))
    FailOption("MixedPixelOptions.min_plate_spread", "must be above 0, got ", min_plate_spread);
}

namespace matte {
namespace {

// The mean colour of the background pixels (alpha 0) in each pixel's window, the spread of their
// colours (the root of the channels' summed variances) and how many there are.
struct GapBackground {
  cv::Mat mean;    // CV_32FC3
  cv::Mat spread;  // CV_32F
  cv::Mat count;   // CV_32F
};

GapBackground BackgroundThroughGaps(const cv::Mat& rgb, const cv::Mat& alpha, int radius) {
  cv::Mat gap;
  cv::Mat(alpha == 0).convertTo(gap, CV_32F, 1.0 / 255.0);
  cv::Mat gap3;
  cv::merge(std::vector<cv::Mat>{gap, gap, gap}, gap3);
  const cv::Mat colour = rgb.mul(gap3), square = colour.mul(rgb);
  const auto window_sum = [radius](const cv::Mat& image) {
    cv::Mat sum;
    cv::boxFilter(image, sum, -1, cv::Size(2 * radius + 1, 2 * radius + 1), cv::Point(-1, -1), false,
                  cv::BORDER_CONSTANT);
    return sum;
  };
  GapBackground background{cv::Mat(rgb.size(), CV_32FC3), cv::Mat(rgb.size(), CV_32F), window_sum(gap)};
  const cv::Mat colour_sum = window_sum(colour), square_sum = window_sum(square);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      const float n = std::max(background.count.at<float>(y, x), 1.0f);
      const cv::Vec3f mean = colour_sum.at<cv::Vec3f>(y, x) / n, mean_square = square_sum.at<cv::Vec3f>(y, x) / n;
      const cv::Vec3f variance = mean_square - mean.mul(mean);
      background.mean.at<cv::Vec3f>(y, x) = mean;
      background.spread.at<float>(y, x) = std::sqrt(std::max(variance[0] + variance[1] + variance[2], 0.0f));
    }
  return background;
}

// How far the purest tree colour near (x, y) stands from the background `behind` it: the largest
// distance among the pixels of alpha >= 0.5 within `radius`, as a colour difference.
cv::Vec3f PurestTreeOffset(const cv::Mat& rgb, const cv::Mat& alpha, int x, int y, const cv::Vec3f& behind,
                           int radius) {
  cv::Vec3f purest(0, 0, 0);
  float farthest = 0;
  for (int v = std::max(0, y - radius); v <= std::min(rgb.rows - 1, y + radius); ++v)
    for (int u = std::max(0, x - radius); u <= std::min(rgb.cols - 1, x + radius); ++u) {
      if (alpha.at<uint8_t>(v, u) < 128) continue;
      const cv::Vec3f offset = rgb.at<cv::Vec3f>(v, u) - behind;
      const float distance = float(cv::norm(offset));
      if (distance > farthest) farthest = distance, purest = offset;
    }
  return purest;
}

// Purity in [0, 1] (CV_32F) of the pixels of `alpha` (CV_8U) at or above options.pure, where
// their background is known: the sky's colour model above its mixed rows, the crown's gaps
// elsewhere; -1 where it is not known, and on every other pixel. `rgb`: CV_32FC3 in [0, 1].
cv::Mat Purity(const cv::Mat& rgb, const cv::Mat& alpha, const SkyEstimate& sky, const MixedPixelOptions& options) {
  CV_Assert(rgb.type() == CV_32FC3 && alpha.type() == CV_8U && rgb.size() == alpha.size());
  cv::Mat purity(rgb.size(), CV_32F, cv::Scalar(-1));
  const int sky_rows = sky.model.valid() ? sky.MixedRowsStart() : 0;
  cv::Mat sky_rgb;
  if (sky_rows > 0) cv::cvtColor(sky.model.Predict(rgb.size()), sky_rgb, cv::COLOR_Lab2RGB);
  const GapBackground gaps = BackgroundThroughGaps(rgb, alpha, options.gap_radius);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      if (alpha.at<uint8_t>(y, x) < options.pure * 255) continue;
      const bool in_sky = y < sky_rows;
      if (!in_sky && gaps.count.at<float>(y, x) < options.min_gap_pixels) continue;
      const cv::Vec3f behind = in_sky ? sky_rgb.at<cv::Vec3f>(y, x) : gaps.mean.at<cv::Vec3f>(y, x);
      const cv::Vec3f tree = PurestTreeOffset(rgb, alpha, x, y, behind, options.tree_radius);
      const double contrast = cv::norm(tree);
      // The sky's model is smooth and known; a background seen through the gaps only where it is
      // uniform against the tree's colour.
      if (contrast <= 0 || (!in_sky && contrast < options.min_contrast * gaps.spread.at<float>(y, x))) continue;
      purity.at<float>(y, x) = float(std::min(1.0, cv::norm(rgb.at<cv::Vec3f>(y, x) - behind) / contrast));
    }
  return purity;
}

// Alpha (CV_32F) told by the clean plate, where it can be: 0 where a pixel of the tree (`alpha`
// nonzero) shows the plate (its colour within options.plate_match of it and under
// options.plate_background of the way to the purest tree colour near it); the share of the way
// where its colour is a mix of the two (within options.plate_line of the line between them); -1
// elsewhere, and where the tree's colour stands too near the plate's (min_contrast times its
// spread). A grey branch in front of brown soil is neither, though far nearer the soil than the
// yellow leaves are: judged by its purity against them, the branches were lost.
cv::Mat PlateAlpha(const cv::Mat& rgb, const cv::Mat& alpha, const voltree::CleanPlate& plate,
                   const MixedPixelOptions& options) {
  cv::Mat told(rgb.size(), CV_32F, cv::Scalar(-1));
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      if (alpha.at<uint8_t>(y, x) == 0 || !plate.Known(x, y)) continue;
      const cv::Vec3f behind(plate.colour.at(x, y, 0), plate.colour.at(x, y, 1), plate.colour.at(x, y, 2));
      const cv::Vec3f tree = PurestTreeOffset(rgb, alpha, x, y, behind, options.tree_radius);
      const double contrast = cv::norm(tree);
      if (contrast < options.min_contrast * std::max(double(plate.spread.at(x, y)), options.min_plate_spread)) continue;
      const cv::Vec3f offset = rgb.at<cv::Vec3f>(y, x) - behind;
      const double share = offset.dot(tree) / (contrast * contrast);
      const double mean_difference = (std::abs(offset[0]) + std::abs(offset[1]) + std::abs(offset[2])) / 3;
      if (mean_difference < options.plate_match && share < options.plate_background)
        told.at<float>(y, x) = 0;
      else if (options.plate_line > 0 && share > 0 && cv::norm(offset - float(share) * tree) < options.plate_line)
        told.at<float>(y, x) = float(std::min(share, 1.0));
    }
  return told;
}

}  // namespace
}  // namespace matte

Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const MatteOptions& matte_options,
                        const MixedPixelOptions& options) {
  const matte::SkyEstimate sky = matte::EstimatePhotoSky(matte::View(photo), matte_options);
  const Image8 clear_sky = matte::ToImage8(sky.ClearSky());
  return MatteMixedPixels(photo, matte, sky, &clear_sky, nullptr, matte_options, options);
}

Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const matte::SkyEstimate& sky,
                        const Image8* clear_sky, const CleanPlate* plate, const MatteOptions& matte_options,
                        const MixedPixelOptions& options) {
  const cv::Mat rgb8 = matte::View(photo), alpha = matte::View(matte);
  const cv::Mat rgb = matte::ToFloat(photo);
  const cv::Mat purity = matte::Purity(rgb, alpha, sky, options);
  // Purity -1 (background unknown): the pixel stays what the matte said.
  const cv::Mat plate_alpha =
      plate != nullptr ? matte::PlateAlpha(rgb, alpha, *plate, options) : cv::Mat(alpha.size(), CV_32F, cv::Scalar(-1));
  // The plate's word on a mixed pixel overrules the matte's whole.
  const cv::Mat whole = (alpha >= options.pure * 255) & ((purity >= options.pure) | (purity < 0)) &
                        ((plate_alpha < 0) | (plate_alpha >= options.pure));
  cv::Mat trimap(alpha.size(), CV_8U, cv::Scalar(128));
  trimap.setTo(255, whole);
  trimap.setTo(0, alpha == 0);
  if (clear_sky != nullptr) trimap.setTo(0, matte::View(*clear_sky) != 0);
  // Where the clean plate is known, a pixel that shows it is background, whatever the matte said.
  trimap.setTo(0, plate_alpha == 0);
  cv::Mat estimate;
  alpha.convertTo(estimate, CV_32F, 1.0 / 255.0);
  estimate.setTo(0.0f, trimap == 0);
  const cv::Mat solved = matte::RefineAlpha(rgb8, estimate, trimap, trimap == 128, matte_options);
  return matte::ToImage8(matte::AlphaTo8(solved));
}

}  // namespace voltree
