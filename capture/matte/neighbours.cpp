#include "capture/matte/neighbours.h"

#include <algorithm>
#include <numeric>

namespace voltree::matte {

std::vector<size_t> NearestViews(const std::vector<voltree::View>& views, size_t target, int count) {
  std::vector<size_t> order(views.size());
  std::iota(order.begin(), order.end(), size_t(0));
  order.erase(order.begin() + target);
  const Eigen::Vector3d center = views[target].pose.Center();
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return (views[a].pose.Center() - center).squaredNorm() < (views[b].pose.Center() - center).squaredNorm();
  });
  order.resize(std::min(order.size(), size_t(std::max(count, 0))));
  return order;
}

void DepthMaps(const voltree::View& from, const voltree::View& to, Depth depth, double ground_z, cv::Mat* map_x,
               cv::Mat* map_y, cv::Rect roi) {
  *map_x = cv::Mat(from.camera.height, from.camera.width, CV_32F, cv::Scalar(-1));
  *map_y = cv::Mat(from.camera.height, from.camera.width, CV_32F, cv::Scalar(-1));
  const cv::Rect image(0, 0, from.camera.width, from.camera.height);
  roi = roi.empty() ? image : roi & image;
  const Eigen::Vector3d from_center = from.pose.Center(), to_center = to.pose.Center();
  for (int y = roi.y; y < roi.y + roi.height; ++y)
    for (int x = roi.x; x < roi.x + roi.width; ++x) {
      const Eigen::Vector3d ray = from.PixelRay({x + 0.5, y + 0.5});
      Eigen::Vector3d point;
      if (depth == Depth::kGround) {
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

}  // namespace voltree::matte
