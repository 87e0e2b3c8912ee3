// Internal: from a photo to a first alpha estimate and a trimap.
// Above the horizon the background is sky, known per pixel from the sky colour model, so alpha
// follows from colour: the fraction of the way from the sky colour to the local leaf colour.
// Below it the ground is textured and may look like bark or leaves, so GrabCut, seeded with the
// tree above the horizon and the trunk columns, decides trunk versus ground (a hard mask whose
// edges become the unknown band; inside it, pixels coloured like the photo's own ground are
// unknown too: GrabCut closes the gaps of a sparse crown).
#pragma once

#include <opencv2/core.hpp>

#include "capture/matte/options.h"

namespace voltree::matte {

struct Segmentation {
  cv::Mat alpha;   // CV_32F in [0, 1]: colour alpha above the horizon, GrabCut mask below
  cv::Mat trimap;  // CV_8U: 0 background, 128 unknown, 255 foreground
  // CV_8U, non-zero where the refinement decides alpha: the unknown band around GrabCut's hard
  // edges, and sky pixels where the leaf and sky colours are too alike for the colour alpha.
  // Elsewhere in the unknown region the colour alpha stands (the sky behind it is known).
  cv::Mat solve;
  int horizon_row = 0;  // first ground row; == rows when there is no ground
  double sky_sigma = 0.0;
};

// `rgb`: CV_8UC3 RGB photo.
Segmentation SegmentTree(const cv::Mat& rgb, const MatteOptions& options);

// Fraction of the way from `background` to `foreground` along their difference (both CV_32FC3),
// clamped to [0, 1]; where the two are closer than `min_contrast`, `fallback` (CV_32F) is used.
// CV_8U mask where `background` and `foreground` (CV_32FC3) are closer than `min_contrast`.
cv::Mat LowContrast(const cv::Mat& background, const cv::Mat& foreground, float min_contrast = 0.04f);

cv::Mat ProjectAlpha(const cv::Mat& image, const cv::Mat& background, const cv::Mat& foreground,
                     const cv::Mat& fallback, float min_contrast = 0.04f);

}  // namespace voltree::matte
