// Internal: fills the holes of an image from its known pixels (push-pull over a pyramid), used to
// estimate the background behind the tree.
#pragma once

#include <opencv2/core.hpp>

namespace voltree::matte {

// `image`: CV_32FC(n); `weight`: CV_32F in [0, 1], 1 where the pixel is known. Known pixels keep
// their value; unknown ones get a smooth blend of the nearest known ones, coarser the farther.
// With no known pixel at all the result is zero.
cv::Mat PushPullFill(const cv::Mat& image, const cv::Mat& weight);

}  // namespace voltree::matte
