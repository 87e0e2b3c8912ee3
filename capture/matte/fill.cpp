#include "capture/matte/fill.h"

#include <vector>

#include <opencv2/imgproc.hpp>

namespace voltree::matte {

cv::Mat PushPullFill(const cv::Mat& image, const cv::Mat& weight) {
  CV_Assert(image.depth() == CV_32F && weight.type() == CV_32F && image.size() == weight.size());
  // Push: premultiplied colours and coverage averaged down to 1 pixel.
  std::vector<cv::Mat> sums{}, weights{};
  cv::Mat channels_weight;
  {
    std::vector<cv::Mat> copies(image.channels(), weight);
    cv::merge(copies, channels_weight);
  }
  sums.push_back(image.mul(channels_weight));
  weights.push_back(weight.clone());
  while (sums.back().cols > 1 || sums.back().rows > 1) {
    const cv::Size half((sums.back().cols + 1) / 2, (sums.back().rows + 1) / 2);
    cv::Mat s, w;
    cv::resize(sums.back(), s, half, 0, 0, cv::INTER_AREA);
    cv::resize(weights.back(), w, half, 0, 0, cv::INTER_AREA);
    sums.push_back(s);
    weights.push_back(w);
  }
  // Pull: at each level the known part plus the coarser estimate where coverage is missing.
  cv::Mat estimate;
  for (int level = static_cast<int>(sums.size()) - 1; level >= 0; --level) {
    const cv::Mat& w = weights[level];
    cv::Mat mean = sums[level].clone();
    for (int y = 0; y < mean.rows; ++y) {
      float* m = mean.ptr<float>(y);
      const float* wy = w.ptr<float>(y);
      const float* up = estimate.empty() ? nullptr : estimate.ptr<float>(y);
      for (int x = 0; x < mean.cols; ++x) {
        // Normalize where coverage is good; blend towards the coarser level where it is thin.
        const float coverage = std::min(1.0f, wy[x]);
        for (int c = 0; c < mean.channels(); ++c) {
          float& v = m[x * mean.channels() + c];
          const float known = wy[x] > 1e-6f ? v / wy[x] : 0.0f;
          const float coarse = up ? up[x * mean.channels() + c] : known;
          v = coverage * known + (1.0f - coverage) * coarse;
        }
      }
    }
    estimate = mean;
    if (level > 0) cv::resize(estimate, estimate, sums[level - 1].size(), 0, 0, cv::INTER_LINEAR);
  }
  return estimate;
}

}  // namespace voltree::matte
