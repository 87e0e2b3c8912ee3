#include "capture/matte/grabcut.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace voltree::matte {

cv::Mat GrabCutForeground(const cv::Mat& rgb, const cv::Mat& labels, int iterations, int max_side) {
  CV_Assert(rgb.type() == CV_8UC3 && labels.type() == CV_8U && rgb.size() == labels.size());
  const double scale = std::min(1.0, double(max_side) / std::max(rgb.rows, rgb.cols));
  cv::Mat small = rgb, mask = labels.clone();
  if (scale < 1.0) {
    const cv::Size size(std::max(1, int(std::lround(rgb.cols * scale))),
                        std::max(1, int(std::lround(rgb.rows * scale))));
    cv::resize(rgb, small, size, 0, 0, cv::INTER_AREA);
    cv::resize(labels, mask, size, 0, 0, cv::INTER_NEAREST);
  }
  cv::theRNG().state = 0x5eed;
  cv::Mat background_model, foreground_model;
  cv::grabCut(small, mask, cv::Rect(), background_model, foreground_model, iterations, cv::GC_INIT_WITH_MASK);
  cv::Mat foreground = (mask == cv::GC_FGD) | (mask == cv::GC_PR_FGD), full;
  cv::resize(foreground, full, rgb.size(), 0, 0, cv::INTER_NEAREST);
  return full;
}

}  // namespace voltree::matte
