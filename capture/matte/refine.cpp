#include "capture/matte/refine.h"

#include <algorithm>

#include <opencv2/alphamat.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_filter.hpp>

namespace voltree::matte {

namespace {

// Known trimap pixels take their label; unknown ones the solved value, clamped.
cv::Mat ApplyTrimap(cv::Mat alpha, const cv::Mat& trimap) {
  cv::min(cv::max(alpha, 0.0), 1.0, alpha);
  alpha.setTo(0.0f, trimap == 0);
  alpha.setTo(1.0f, trimap == 255);
  return alpha;
}

cv::Mat GuidedRefine(const cv::Mat& rgb, const cv::Mat& estimate, const MatteOptions& options) {
  // The radius is given for 256-pixel images and follows the image size.
  const int radius = std::max(1, options.guided_radius * std::min(rgb.rows, rgb.cols) / 256);
  cv::Mat guide, filtered;
  rgb.convertTo(guide, CV_32F, 1.0 / 255.0);
  cv::ximgproc::guidedFilter(guide, estimate, filtered, radius, options.guided_epsilon, CV_32F);
  return filtered;
}

}  // namespace

cv::Mat InfoFlowOnTiles(const cv::Mat& rgb, const cv::Mat& estimate, const cv::Mat& trimap, const cv::Mat& solve,
                        int tile) {
  cv::Mat alpha = estimate.clone();
  const int margin = std::max(8, tile / 8);
  for (int y0 = 0; y0 < rgb.rows; y0 += tile)
    for (int x0 = 0; x0 < rgb.cols; x0 += tile) {
      const cv::Rect core(x0, y0, std::min(tile, rgb.cols - x0), std::min(tile, rgb.rows - y0));
      const cv::Mat core_solve = solve(core) & (trimap(core) == 128);
      if (cv::countNonZero(core_solve) == 0) continue;
      const cv::Rect context = cv::Rect(x0 - margin, y0 - margin, core.width + 2 * margin, core.height + 2 * margin) &
                               cv::Rect(0, 0, rgb.cols, rgb.rows);
      const cv::Mat context_trimap = trimap(context).clone();
      if (cv::countNonZero(context_trimap == 0) == 0 || cv::countNonZero(context_trimap == 255) == 0 ||
          cv::countNonZero(context_trimap == 128) < kMinInfoFlowUnknown)
        continue;
      cv::Mat solved;
      try {
        cv::alphamat::infoFlow(rgb(context).clone(), context_trimap, solved);
      } catch (const cv::Exception&) {
        continue;  // a degenerate tile (e.g. a singular system) keeps the first estimate
      }
      cv::Mat solved_float;
      solved.convertTo(solved_float, CV_32F, solved.depth() == CV_8U ? 1.0 / 255.0 : 1.0);
      const cv::Rect inner(core.x - context.x, core.y - context.y, core.width, core.height);
      solved_float(inner).copyTo(alpha(core), core_solve);
    }
  return alpha;
}

cv::Mat RefineAlpha(const cv::Mat& rgb, const cv::Mat& estimate, const cv::Mat& trimap, const cv::Mat& solve,
                    const MatteOptions& options) {
  CV_Assert(rgb.type() == CV_8UC3 && estimate.type() == CV_32F && trimap.type() == CV_8U && solve.type() == CV_8U);
  cv::Mat alpha = estimate.clone();
  switch (options.refine) {
    case RefineMethod::kGuided:
      GuidedRefine(rgb, estimate, options).copyTo(alpha, solve);
      break;
    case RefineMethod::kInfoFlow:
      alpha = InfoFlowOnTiles(rgb, estimate, trimap, solve, options.infoflow_tile);
      break;
    case RefineMethod::kNone:
      break;
  }
  return ApplyTrimap(alpha, trimap);
}

}  // namespace voltree::matte
