#include "capture/matte/backdrop.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "capture/matte/neighbours.h"
#include "core/error.h"

namespace voltree {

void BackdropOptions::Check() const {
  if (neighbours < 1) FailOption("BackdropOptions.neighbours", "must be at least 1, got ", neighbours);
  if (far_patch_radius < 0 || far_patch_radius > 16)
    FailOption("BackdropOptions.far_patch_radius", "must be in [0, 16], got ", far_patch_radius);
  if (ground_patch_radius < 0 || ground_patch_radius > 16)
    FailOption("BackdropOptions.ground_patch_radius", "must be in [0, 16], got ", ground_patch_radius);
  if (behind_neighbours < 0)
    FailOption("BackdropOptions.behind_neighbours", "must be at least 0, got ", behind_neighbours);
  if (behind_min_views < 1)
    FailOption("BackdropOptions.behind_min_views", "must be at least 1, got ", behind_min_views);
  if (behind_patch_radius < 0 || behind_patch_radius > 16)
    FailOption("BackdropOptions.behind_patch_radius", "must be in [0, 16], got ", behind_patch_radius);
  if (!(behind_step_pixels >= 0.25 && behind_step_pixels <= 16))
    FailOption("BackdropOptions.behind_step_pixels", "must be in [0.25, 16], got ", behind_step_pixels);
  if (!(max_difference > 0 && max_difference < 1))
    FailOption("BackdropOptions.max_difference", "must be in (0, 1), got ", max_difference);
}

Image8 ExplainedByBackdrop(const std::vector<View>& views, const std::vector<Image8>& photos,
                           const std::vector<Image8>& mattes, size_t target, const BackdropOptions& options) {
  options.Check();
  if (views.size() != photos.size() || (!mattes.empty() && mattes.size() != views.size()) || target >= views.size())
    Fail("backdrop parallax needs one photo per view (", views.size(), " views, ", photos.size(), " photos)");
  const cv::Mat image = matte::ToFloat(photos[target]);
  cv::Mat best(image.size(), CV_32F, cv::Scalar(1e9));
  for (size_t neighbour : matte::NearestViews(views, target, options.neighbours)) {
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
      matte::DepthMaps(views[target], views[neighbour], ground ? matte::Depth::kGround : matte::Depth::kFar,
                       options.ground_z, &map_x, &map_y);
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

namespace {

constexpr int kMaxSweepSteps = 4096;

// Mean absolute RGB difference of the (2r+1)^2 patches around `a` in `first` and `b` in `second`
// (both inside by r), or early out with a value >= `limit` once the patch cannot come under it.
float PatchDifference(const cv::Mat& first, cv::Point a, const cv::Mat& second, cv::Point b, int r, float limit) {
  const float count = float((2 * r + 1) * (2 * r + 1));
  const float budget = limit * 3 * count;
  float sum = 0;
  for (int dy = -r; dy <= r; ++dy) {
    const cv::Vec3f* row_a = first.ptr<cv::Vec3f>(a.y + dy) + a.x;
    const cv::Vec3f* row_b = second.ptr<cv::Vec3f>(b.y + dy) + b.x;
    for (int dx = -r; dx <= r; ++dx) {
      const cv::Vec3f d = row_a[dx] - row_b[dx];
      sum += std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]);
    }
    if (sum >= budget) return limit;
  }
  return sum / (3 * count);
}

// One neighbour as the sweep sees it: its photo, where its hull hides the backdrop, and the
// target's camera centre in its camera frame.
struct SweepNeighbour {
  const View* view;
  cv::Mat image, hidden;
  Eigen::Vector3d target_center;
  // The point at inverse distance w along the target's ray (`direction`, in this camera's frame):
  // (center + direction / w) * w is linear in w, and w = 0 is the ray's vanishing point.
  bool Project(const Eigen::Vector3d& direction, double w, Eigen::Vector2d* pixel) const {
    const Eigen::Vector3d point = w * target_center + direction;
    if (point.z() <= 1e-9) return false;
    *pixel = view->camera.Project(point);
    return true;
  }
};

// The depths swept along one ray: inverse distances from w_far (the ground, or 0 at infinity) to
// w_near (the hull's far side), in steps no longer than `step_pixels` in any neighbour.
struct RaySweep {
  double w_near = 0, w_far = 0;
  int steps = 0;
  double W(int step) const { return w_far + (w_near - w_far) * step / steps; }
};

RaySweep SweepOfRay(const View& view, const Eigen::Vector3d& ray, double far_depth,
                    const std::vector<SweepNeighbour>& neighbours, const BackdropOptions& options) {
  RaySweep sweep;
  sweep.w_near = ray.dot(view.pose.ViewDirection()) / far_depth;
  const double height = view.pose.Center().z() - options.ground_z;
  if (ray.z() < 0 && height > 0) sweep.w_far = -ray.z() / height;
  if (!(sweep.w_near > sweep.w_far)) return sweep;  // the ground comes before the hull's far side: no steps
  sweep.steps = 1;
  for (const SweepNeighbour& neighbour : neighbours) {
    const Eigen::Vector3d direction = neighbour.view->pose.rotation * ray;
    Eigen::Vector2d near_pixel, far_pixel;
    if (neighbour.Project(direction, sweep.w_near, &near_pixel) &&
        neighbour.Project(direction, sweep.w_far, &far_pixel))
      sweep.steps = std::max(sweep.steps, int(std::ceil((near_pixel - far_pixel).norm() / options.behind_step_pixels)));
  }
  sweep.steps = std::min(sweep.steps, kMaxSweepSteps);
  return sweep;
}

// Whether, at some depth of `sweep`, at least `min_views` neighbours show the patch around `pixel`
// of `image` where their hull does not hide it (a step either way allowed). `hits` and `agreeing`
// are scratch space of kMaxSweepSteps + 1.
bool ShownBehind(const cv::Mat& image, cv::Point pixel, const Eigen::Vector3d& ray, const RaySweep& sweep,
                 const std::vector<SweepNeighbour>& neighbours, const BackdropOptions& options,
                 std::vector<uint8_t>& hits, std::vector<uint8_t>& agreeing) {
  const int r = options.behind_patch_radius;
  const float limit = float(options.max_difference);
  std::fill(agreeing.begin(), agreeing.begin() + sweep.steps + 1, uint8_t(0));
  for (const SweepNeighbour& neighbour : neighbours) {
    const Eigen::Vector3d direction = neighbour.view->pose.rotation * ray;
    std::fill(hits.begin(), hits.begin() + sweep.steps + 1, uint8_t(0));
    bool any = false;
    for (int step = 0; step <= sweep.steps; ++step) {
      Eigen::Vector2d at;
      if (!neighbour.Project(direction, sweep.W(step), &at)) continue;
      const cv::Point q(int(std::floor(at.x())), int(std::floor(at.y())));
      if (q.x < r || q.y < r || q.x >= neighbour.image.cols - r || q.y >= neighbour.image.rows - r) continue;
      if (neighbour.hidden.at<uint8_t>(q) != 0) continue;
      hits[step] = PatchDifference(image, pixel, neighbour.image, q, r, limit) < limit;
      any = any || hits[step];
    }
    if (!any) continue;
    for (int step = 0; step <= sweep.steps; ++step) {
      agreeing[step] += hits[step] || (step > 0 && hits[step - 1]) || (step < sweep.steps && hits[step + 1]);
      if (agreeing[step] >= options.behind_min_views) return true;
    }
  }
  return false;
}

}  // namespace

Image8 ExplainedBehindHull(const std::vector<View>& views, const std::vector<Image8>& photos,
                           const std::vector<HullProjection>& hulls, size_t target, const Image8& region,
                           const BackdropOptions& options) {
  options.Check();
  if (views.size() != photos.size() || views.size() != hulls.size() || target >= views.size())
    Fail("the sweep behind the hull needs one photo and one hull per view (", views.size(), " views, ", photos.size(),
         " photos, ", hulls.size(), " hulls)");
  const View& view = views[target];
  const int r = options.behind_patch_radius;
  std::vector<SweepNeighbour> neighbours;
  for (size_t n : matte::NearestViews(views, target, options.behind_neighbours)) {
    SweepNeighbour neighbour{&views[n], matte::ToFloat(photos[n]), cv::Mat(),
                             views[n].pose.ToCamera(view.pose.Center())};
    // The hull grown by a patch: a patch touching it may hold the tree.
    cv::dilate(matte::View(hulls[n].mask), neighbour.hidden,
               cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * r + 3, 2 * r + 3)));
    neighbours.push_back(std::move(neighbour));
  }
  const cv::Mat image = matte::ToFloat(photos[target]);
  const cv::Mat inside = matte::View(region);
  cv::Mat explained = cv::Mat::zeros(image.size(), CV_8UC1);
  std::vector<uint8_t> hits(kMaxSweepSteps + 1), agreeing(kMaxSweepSteps + 1);
  for (int y = r; y < image.rows - r; ++y)
    for (int x = r; x < image.cols - r; ++x) {
      if (inside.at<uint8_t>(y, x) == 0) continue;
      const Eigen::Vector3d ray = view.PixelRay({x + 0.5, y + 0.5});
      const RaySweep sweep = SweepOfRay(view, ray, hulls[target].far_depth, neighbours, options);
      if (sweep.steps > 0 && ShownBehind(image, {x, y}, ray, sweep, neighbours, options, hits, agreeing))
        explained.at<uint8_t>(y, x) = 255;
    }
  return matte::ToImage8(explained);
}

}  // namespace voltree
