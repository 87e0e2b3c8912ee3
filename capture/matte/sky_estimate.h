// Internal: the sky one photo shows. The smooth colour model (sky.h) is seeded by the top rows and
// refitted to all the sky above the horizon; the pixels it explains, the clouds it cannot follow,
// and the horizon below which the ground begins come with it.
#pragma once

#include <opencv2/core.hpp>

#include "capture/matte/options.h"
#include "capture/matte/sky.h"

namespace voltree::matte {

struct SkyEstimate {
  SkyModel model;   // invalid when the top rows show no smooth sky (a camera looking down)
  cv::Mat pixels;   // CV_8U, 255 where the model or the cloud test explains the pixel
  cv::Mat clouds;   // CV_8U, 255 on bright, nearly grey pixels (part of `pixels`)
  int horizon = 0;  // first ground row; == rows when there is no ground
  double Tolerance(const MatteOptions& options) const;  // Lab distance still called sky
  // The rows just above the horizon mix sky and ground (blur, JPEG, antialiasing): the first row
  // of those, below which the colour model does not speak.
  int MixedRowsStart() const;
  // CV_8U, 255 where the photo certainly shows sky: explained by the model above the mixed rows.
  // Clouds apart: bright, grey bark passes their test.
  cv::Mat ClearSky() const;
};

// `lab`: CV_32FC3 CIELab photo.
SkyEstimate EstimateSky(const cv::Mat& lab, const MatteOptions& options);

// The same from an 8-bit RGB photo (CV_8UC3).
SkyEstimate EstimatePhotoSky(const cv::Mat& rgb8, const MatteOptions& options);

// The horizon from a sky mask: the row after the last one that still shows sky across at least
// `min_fraction` of its width and a fifth of the sky-richest row (the ground shows none or a few
// stray pixels). 0 when no row shows sky.
int EstimateHorizonRow(const cv::Mat& sky_mask, double min_fraction = 0.03);

// CV_8U mask of the first `horizon` rows of a rows x cols image.
cv::Mat RowsAbove(int rows, int cols, int horizon);

}  // namespace voltree::matte
