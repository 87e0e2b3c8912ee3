#include "capture/normalize_hull.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/normalize.h"
#include "core/error.h"

namespace voltree {

void HullOptions::Check() const {
  if (resolution < 4 || resolution > 1024) FailOption("HullOptions.resolution", "must be in 4..1024, got ", resolution);
  if (!(matte_threshold > 0 && matte_threshold < 1))
    FailOption("HullOptions.matte_threshold", "must be in (0, 1), got ", matte_threshold);
  if (!(min_seen_fraction > 0 && min_seen_fraction <= 1))
    FailOption("HullOptions.min_seen_fraction", "must be in (0, 1], got ", min_seen_fraction);
}

namespace {

// A matte as a binary "tree here" mask, dilated by `radius` pixels.
Image8 DilatedMask(const Image8& matte, double threshold, int radius) {
  if (matte.channels != 1) Fail("a matte must have one channel, got ", matte.channels);
  cv::Mat in(matte.height, matte.width, CV_8UC1, const_cast<uint8_t*>(matte.pixels.data()));
  cv::Mat mask;
  cv::threshold(in, mask, threshold * 255.0, 255, cv::THRESH_BINARY);
  if (radius > 0)
    cv::dilate(mask, mask, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
  Image8 out(matte.width, matte.height, 1);
  std::copy(mask.datastart, mask.dataend, out.pixels.begin());
  return out;
}

}  // namespace

VisualHull CarveVisualHull(const std::vector<View>& views, const std::vector<Image8>& mattes,
                           const Eigen::Vector3d& region_min, const Eigen::Vector3d& region_max,
                           const HullOptions& options) {
  options.Check();
  if (views.size() != mattes.size() || views.empty())
    Fail("visual hull needs one matte per view (", views.size(), " views, ", mattes.size(), " mattes)");
  const Eigen::Vector3d extent = region_max - region_min;
  if (!(extent.minCoeff() > 0)) Fail("visual hull region is empty");
  const double voxel = extent.maxCoeff() / options.resolution;
  const Eigen::Vector3i cells = (extent / voxel).array().ceil().cast<int>().max(1);
  const Eigen::Vector3d region_center = 0.5 * (region_min + region_max);

  // Per view: the dilated mask and the scale from camera pixels to matte pixels.
  std::vector<Image8> masks(views.size());
  std::vector<Eigen::Vector2d> to_matte(views.size());
  for (size_t v = 0; v < views.size(); ++v) {
    const Camera& camera = views[v].camera;
    to_matte[v] = {double(mattes[v].width) / camera.width, double(mattes[v].height) / camera.height};
    const double depth = std::max(views[v].pose.ToCamera(region_center).z(), 1e-9);
    const double radius = camera.FocalX() * to_matte[v].x() * voxel * 0.87 / depth;  // half-diagonal
    masks[v] = DilatedMask(mattes[v], options.matte_threshold, int(std::ceil(radius)) + 1);
  }
  const int min_seen = std::max(1, int(std::ceil(options.min_seen_fraction * double(views.size()))));

  std::vector<uint8_t> kept(size_t(cells.x()) * cells.y() * cells.z(), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, cells.z()), [&](const tbb::blocked_range<int>& slices) {
    for (int z = slices.begin(); z < slices.end(); ++z)
      for (int y = 0; y < cells.y(); ++y)
        for (int x = 0; x < cells.x(); ++x) {
          const Eigen::Vector3d center = region_min + voxel * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5);
          int seen = 0;
          bool carved = false;
          for (size_t v = 0; v < views.size() && !carved; ++v) {
            Eigen::Vector2d pixel;
            if (!views[v].WorldToPixel(center, &pixel)) continue;
            const int px = int(std::floor(pixel.x() * to_matte[v].x()));
            const int py = int(std::floor(pixel.y() * to_matte[v].y()));
            if (px < 0 || py < 0 || px >= masks[v].width || py >= masks[v].height) continue;
            ++seen;
            carved = masks[v].at(px, py) == 0;
          }
          kept[(size_t(z) * cells.y() + y) * cells.x() + x] = !carved && seen >= min_seen;
        }
  });

  VisualHull hull;
  hull.voxel_size = voxel;
  Eigen::Vector3i low = cells, high(-1, -1, -1);
  for (int z = 0; z < cells.z(); ++z)
    for (int y = 0; y < cells.y(); ++y)
      for (int x = 0; x < cells.x(); ++x)
        if (kept[(size_t(z) * cells.y() + y) * cells.x() + x]) {
          ++hull.voxels;
          low = low.cwiseMin(Eigen::Vector3i(x, y, z));
          high = high.cwiseMax(Eigen::Vector3i(x, y, z));
        }
  if (hull.voxels == 0)
    Fail(
        "the visual hull is empty: no point is on the tree in every photo (do the mattes match the images "
        "and the cameras?)");
  hull.bounds_min = region_min + voxel * low.cast<double>();
  hull.bounds_max = region_min + voxel * (high + Eigen::Vector3i::Ones()).cast<double>();
  Eigen::Vector2d base_sum = Eigen::Vector2d::Zero();
  int base_count = 0;
  for (int y = 0; y < cells.y(); ++y)
    for (int x = 0; x < cells.x(); ++x)
      if (kept[(size_t(low.z()) * cells.y() + y) * cells.x() + x]) {
        base_sum += Eigen::Vector2d(x + 0.5, y + 0.5);
        ++base_count;
      }
  const Eigen::Vector2d base_cell = base_sum / base_count;
  hull.base = region_min + voxel * Eigen::Vector3d(base_cell.x(), base_cell.y(), low.z());
  return hull;
}

VisualHull CarveVisualHullAuto(const std::vector<View>& views, const std::vector<Image8>& mattes,
                               const HullOptions& options) {
  const Eigen::Vector3d target = LookAtPoint(views);
  double distance = 0;
  for (const View& view : views) distance += (view.pose.Center() - target).norm();
  distance /= double(views.size());
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(distance);
  const VisualHull coarse = CarveVisualHull(views, mattes, target - half, target + half, options);
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(2 * coarse.voxel_size);
  return CarveVisualHull(views, mattes, coarse.bounds_min - margin, coarse.bounds_max + margin, options);
}

}  // namespace voltree
