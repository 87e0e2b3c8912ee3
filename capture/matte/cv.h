// Internal to the matting files: views and conversions between voltree images and cv::Mat, and a
// disc for morphology.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/image.h"

namespace voltree::matte {

// A cv::Mat header over the pixels of `image` (no copy); valid while `image` lives.
inline cv::Mat View(Image8& image) {
  return cv::Mat(image.height, image.width, CV_8UC(image.channels), image.pixels.data());
}
inline cv::Mat View(const Image8& image) { return View(const_cast<Image8&>(image)).clone(); }

// 8-bit RGB -> float RGB in [0, 1].
inline cv::Mat ToFloat(const Image8& rgb) {
  cv::Mat out;
  View(const_cast<Image8&>(rgb)).convertTo(out, CV_32F, 1.0 / 255.0);
  return out;
}

// A CV_8UC1..4 Mat -> Image8 (copies).
inline Image8 ToImage8(const cv::Mat& mat) {
  CV_Assert(mat.depth() == CV_8U);
  Image8 image(mat.cols, mat.rows, mat.channels());
  cv::Mat view = View(image);
  mat.copyTo(view);
  return image;
}

// Float alpha in [0, 1] -> 8-bit, rounded.
inline cv::Mat AlphaTo8(const cv::Mat& alpha) {
  cv::Mat out;
  alpha.convertTo(out, CV_8U, 255.0, 0.0);  // convertTo rounds and saturates
  return out;
}

// A filled disc of `radius` pixels, for morphology.
inline cv::Mat Disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

}  // namespace voltree::matte
