#include "capture/matte/image.h"

#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "capture/matte/foreground.h"
#include "capture/matte/refine.h"
#include "capture/matte/trimap.h"
#include "core/error.h"

namespace voltree {

MatteResult MatteImage(const Image8& photo, const MatteOptions& options) {
  if (photo.channels < 3) Fail("MatteImage: expected an RGB photo, got ", photo.channels, " channels");
  cv::Mat rgb;
  if (photo.channels == 4)
    cv::cvtColor(matte::View(photo), rgb, cv::COLOR_RGBA2RGB);
  else
    rgb = matte::View(photo);
  const matte::Segmentation segmentation = matte::SegmentTree(rgb, options);
  const cv::Mat alpha = matte::RefineAlpha(rgb, segmentation.alpha, segmentation.trimap, segmentation.solve, options);

  MatteResult result;
  result.alpha = matte::ToImage8(matte::AlphaTo8(alpha));
  result.trimap = matte::ToImage8(segmentation.trimap);
  result.foreground = PremultipliedForeground(photo, result.alpha);
  result.horizon_row = segmentation.horizon_row;
  return result;
}

}  // namespace voltree
