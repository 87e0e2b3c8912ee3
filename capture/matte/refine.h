// Internal: solves the unknown band of a trimap (see RefineMethod).
#pragma once

#include <opencv2/core.hpp>

#include "capture/matte/options.h"

namespace voltree::matte {

// `rgb`: CV_8UC3; `estimate`: CV_32F first alpha in [0, 1]; `trimap`: CV_8U 0/128/255;
// `solve`: CV_8U, where the method replaces the estimate (unknown pixels only).
// Returns CV_32F alpha in [0, 1], exactly 0 / 1 where the trimap is known.
cv::Mat RefineAlpha(const cv::Mat& rgb, const cv::Mat& estimate, const cv::Mat& trimap, const cv::Mat& solve,
                    const MatteOptions& options);

// alphamat::infoFlow on the tiles that hold `solve` pixels, each with a margin of context; only
// `solve` pixels are written. Tiles whose context has no known foreground or background, or
// fewer than kMinInfoFlowUnknown unknown pixels, keep `estimate`.
// alphamat::infoFlow (OpenCV 4.6) reads past its neighbour lists, and crashes, when the trimap has
// fewer unknown pixels than its nearest-neighbour searches ask for (measured: 1-4 crash, 5 do not).
constexpr int kMinInfoFlowUnknown = 16;

cv::Mat InfoFlowOnTiles(const cv::Mat& rgb, const cv::Mat& estimate, const cv::Mat& trimap, const cv::Mat& solve,
                        int tile);

}  // namespace voltree::matte
