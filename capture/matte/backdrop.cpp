#include "capture/matte/backdrop.h"

#include <algorithm>
#include <numeric>
#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "core/error.h"

namespace voltree {

void BackdropOptions::Check() const {
  if (neighbours < 1) FailOption("BackdropOptions.neighbours", "must be at least 1, got ", neighbours);
  if (far_patch_radius < 0 || far_patch_radius > 16)
    FailOption("BackdropOptions.far_patch_radius", "must be in [0, 16], got ", far_patch_radius);
  if (ground_patch_radius < 0 || ground_patch_radius > 16)
    FailOption("BackdropOptions.ground_patch_radius", "must be in [0, 16], got ", ground_patch_radius);
  if (!(max_difference > 0 && max_difference < 1))
    FailOption("BackdropOptions.max_difference", "must be in (0, 1), got ", max_difference);
}

namespace {

// The views nearest to `target` by camera centre, nearest first.
std::vector<size_t> NearestViews(const std::vector<View>& views, size_t target, int count) {
  std::vector<size_t> order(views.size());
  std::iota(order.begin(), order.end(), size_t(0));
  order.erase(order.begin() + target);
  const Eigen::Vector3d center = views[target].pose.Center();
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return (views[a].pose.Center() - center).squaredNorm() < (views[b].pose.Center() - center).squaredNorm();
  });
  order.resize(std::min(order.size(), size_t(count)));
  return order;
}

// Where each pixel of `from` lands in `to` under one hypothesis, as cv::remap maps (pixel centres
// at integers); -1 where the hypothesis says nothing (the ground above the horizon, behind a camera).
void HypothesisMaps(const View& from, const View& to, bool ground, double ground_z, cv::Mat* map_x, cv::Mat* map_y) {
  *map_x = cv::Mat(from.camera.height, from.camera.width, CV_32F, cv::Scalar(-1));
  *map_y = cv::Mat(from.camera.height, from.camera.width, CV_32F, cv::Scalar(-1));
  const Eigen::Vector3d from_center = from.pose.Center(), to_center = to.pose.Center();
  for (int y = 0; y < from.camera.height; ++y)
    for (int x = 0; x < from.camera.width; ++x) {
      const Eigen::Vector3d ray = from.PixelRay({x + 0.5, y + 0.5});
      Eigen::Vector3d point;
      if (ground) {
        if (ray.z() > -1e-6) continue;  // never meets the ground
        const double t = (ground_z - from_center.z()) / ray.z();
        if (t <= 0) continue;
        point = from_center + t * ray;
      } else {
        // Below the horizon the ground is in the way: nothing there is far. (A little below, for
        // distant hills; a pixel of leaves the colour of the grass would be explained otherwise.)
        if (ray.z() < -0.02) continue;
        point = to_center + ray;  // at infinity only the direction matters
      }
      Eigen::Vector2d pixel;
      if (!to.WorldToPixel(point, &pixel)) continue;
      map_x->at<float>(y, x) = float(pixel.x() - 0.5);
      map_y->at<float>(y, x) = float(pixel.y() - 0.5);
    }
}

}  // namespace

Image8 ExplainedByBackdrop(const std::vector<View>& views, const std::vector<Image8>& photos,
                           const std::vector<Image8>& mattes, size_t target, const BackdropOptions& options) {
  options.Check();
  if (views.size() != photos.size() || (!mattes.empty() && mattes.size() != views.size()) || target >= views.size())
    Fail("backdrop parallax needs one photo per view (", views.size(), " views, ", photos.size(), " photos)");
  const cv::Mat image = matte::ToFloat(photos[target]);
  cv::Mat best(image.size(), CV_32F, cv::Scalar(1e9));
  for (size_t neighbour : NearestViews(views, target, options.neighbours)) {
    const cv::Mat other = matte::ToFloat(photos[neighbour]);
    // Ground the neighbour sees behind its own tree is no ground: the crown seen from above hides
    // the same ground in neighbouring photos, and leaves would match leaves.
    cv::Mat occluder;
    if (!mattes.empty()) {
      cv::threshold(matte::View(mattes[neighbour]), occluder, 0, 255, cv::THRESH_BINARY);
      cv::dilate(occluder, occluder, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    }
    for (bool ground : {false, true}) {
      cv::Mat map_x, map_y, warped, valid;
      HypothesisMaps(views[target], views[neighbour], ground, options.ground_z, &map_x, &map_y);
      cv::remap(other, warped, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(-10, -10, -10));
      cv::Mat difference;
      cv::absdiff(image, warped, difference);
      if (ground && !occluder.empty()) {
        cv::Mat hidden;
        cv::remap(occluder, hidden, map_x, map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(255));
        difference.setTo(cv::Scalar(10, 10, 10), hidden != 0);
      }
      cv::transform(difference, difference, cv::Matx13f(1.f / 3, 1.f / 3, 1.f / 3));  // mean over RGB
      const int radius = ground ? options.ground_patch_radius : options.far_patch_radius;
      if (radius > 0) cv::blur(difference, difference, cv::Size(2 * radius + 1, 2 * radius + 1));
      best = cv::min(best, difference);
    }
  }
  cv::Mat explained = best < options.max_difference;  // 255 where explained
  return matte::ToImage8(explained);
}

}  // namespace voltree
