#include "capture/matte/narrow_parts.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>
#include <vector>

#include "capture/matte/cv.h"
#include "capture/matte/refine.h"

namespace voltree::matte {

cv::Mat NarrowParts(const cv::Mat& inside, int radius) {
  cv::Mat wide;
  cv::morphologyEx(inside, wide, cv::MORPH_OPEN, Disc(radius));
  return (inside != 0) & (wide == 0);
}

namespace {

// The narrow parts without the slivers the opening leaves along the crown's outline.
cv::Mat NarrowPartsWithoutSlivers(const cv::Mat& inside, int radius, int band) {
  cv::Mat parts;
  cv::morphologyEx(NarrowParts(inside, radius), parts, cv::MORPH_OPEN, Disc(band));
  return parts;
}

}  // namespace

cv::Mat NarrowCentreLines(const cv::Mat& inside, int radius, int band) {
  const cv::Mat parts = NarrowPartsWithoutSlivers(inside, radius, band);
  cv::Mat centre = cv::Mat::zeros(parts.size(), CV_8UC1);
  if (cv::countNonZero(parts) > 0) cv::ximgproc::thinning(parts, centre);
  return centre;
}

void SolveAgainInside(const cv::Mat& rgb, const cv::Mat& region, const cv::Mat& tree, const cv::Mat& background,
                      const MatteOptions& options, cv::Mat& alpha) {
  cv::Mat trimap(alpha.size(), CV_8UC1, cv::Scalar(128));
  trimap.setTo(0, alpha == 0);
  trimap.setTo(255, alpha == 255);
  trimap.setTo(128, region & (alpha < 255));
  trimap.setTo(255, tree);
  if (!background.empty()) trimap.setTo(0, background);
  cv::Mat estimate;
  alpha.convertTo(estimate, CV_32F, 1.0 / 255.0);
  estimate.setTo(1.0f, trimap == 255);
  estimate.setTo(0.0f, trimap == 0);
  const cv::Mat solved = AlphaTo8(RefineAlpha(rgb, estimate, trimap, region & (trimap == 128), options));
  solved.copyTo(alpha, region);
}

bool MendMissedNarrowParts(const cv::Mat& rgb, const cv::Mat& inside, const cv::Mat& background,
                           const NarrowPartMend& mend, const MatteOptions& options, cv::Mat& alpha) {
  const cv::Mat parts = NarrowPartsWithoutSlivers(inside, mend.radius, mend.band);
  if (cv::countNonZero(parts) == 0) return false;
  cv::Mat centre;
  cv::ximgproc::thinning(parts, centre);
  cv::Mat missed = centre & (alpha <= mend.carve_alpha);
  if (!background.empty()) missed.setTo(0, background != 0);
  cv::Mat labels;
  const int count = cv::connectedComponents(parts, labels, 8, CV_32S);
  std::vector<int> centre_pixels(count, 0), missed_pixels(count, 0);
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) {
      const int label = labels.at<int>(y, x);
      centre_pixels[label] += centre.at<uint8_t>(y, x) != 0;
      missed_pixels[label] += missed.at<uint8_t>(y, x) != 0;
    }
  cv::Mat mended = cv::Mat::zeros(parts.size(), CV_8UC1);
  bool any = false;
  for (int label = 1; label < count; ++label)
    if (missed_pixels[label] >= 2 * mend.radius && missed_pixels[label] > mend.max_missed * centre_pixels[label]) {
      mended.setTo(255, labels == label);
      any = true;
    }
  if (!any) return false;
  SolveAgainInside(rgb, mended, mended & missed, background.empty() ? background : mended & (background != 0), options,
                   alpha);
  return true;
}

}  // namespace voltree::matte
