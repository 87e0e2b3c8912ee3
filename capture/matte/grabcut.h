// Internal: OpenCV's GrabCut as the matting files use it, on a copy no larger than a given side
// (it is slow on whole photos) and from a fixed random state (its GMMs start from k-means on the
// thread's cv::theRNG(), so the result would otherwise depend on what ran before on the thread).
#pragma once

#include <opencv2/core.hpp>

namespace voltree::matte {

// `rgb`: CV_8UC3; `labels`: CV_8U of cv::GC_BGD / GC_FGD / GC_PR_BGD / GC_PR_FGD, the same size.
// Returns CV_8U at `rgb`'s size, 255 where GrabCut settles on the foreground.
cv::Mat GrabCutForeground(const cv::Mat& rgb, const cv::Mat& labels, int iterations, int max_side);

}  // namespace voltree::matte
