#include "capture/matte/foreground.h"

#include <algorithm>
#include <cmath>

#include "capture/matte/cv.h"
#include "capture/matte/fill.h"
#include "core/error.h"

namespace voltree {

Image8 PremultipliedForeground(const Image8& photo, const Image8& alpha) {
  if (photo.width != alpha.width || photo.height != alpha.height || alpha.channels != 1 || photo.channels < 3)
    Fail("PremultipliedForeground: photo is ", photo.width, "x", photo.height, "x", photo.channels, " but matte is ",
         alpha.width, "x", alpha.height, "x", alpha.channels);
  Image8 rgb = photo;
  if (photo.channels != 3) {
    rgb = Image8(photo.width, photo.height, 3);
    for (size_t i = 0; i < size_t(photo.width) * photo.height; ++i)
      for (int c = 0; c < 3; ++c) rgb.pixels[i * 3 + c] = photo.pixels[i * photo.channels + c];
  }
  const cv::Mat image = matte::ToFloat(rgb);
  cv::Mat known(image.size(), CV_32F);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) known.at<float>(y, x) = alpha.at(x, y) == 0 ? 1.0f : 0.0f;
  const cv::Mat background = matte::PushPullFill(image, known);

  Image8 out(photo.width, photo.height, 4);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const float a = alpha.at(x, y) / 255.0f;
      const cv::Vec3f i = image.at<cv::Vec3f>(y, x), b = background.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c) {
        const float premultiplied = std::clamp(i[c] - (1.0f - a) * b[c], 0.0f, a);
        out.at(x, y, c) = static_cast<uint8_t>(std::lround(premultiplied * 255.0f));
      }
      out.at(x, y, 3) = alpha.at(x, y);
    }
  return out;
}

}  // namespace voltree
