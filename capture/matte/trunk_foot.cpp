#include "capture/matte/trunk_foot.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "capture/matte/narrow_parts.h"
#include "core/error.h"

namespace voltree {

void TrunkFootOptions::Check() const {
  hull.Check();
  const auto share = [](const char* field, double value) {
    if (!(value >= 0 && value <= 1)) FailOption(field, "must be in [0, 1], got ", value);
  };
  share("TrunkFootOptions.min_lift", min_lift);
  share("TrunkFootOptions.min_known", min_known);
  share("TrunkFootOptions.min_in_front", min_in_front);
  share("TrunkFootOptions.max_held", max_held);
  if (!(unlike > 0 && unlike < 1)) FailOption("TrunkFootOptions.unlike", "must be in (0, 1), got ", unlike);
}

namespace {

// The stretch from the ground up to `foot` (and one voxel into the hull) as one photo sees it: the
// pixels of its centre line, drawn through points along it so that the lens's distortion is
// honoured. Empty when the stretch is not in front of the camera.
std::vector<cv::Point> StretchPixels(const View& view, const Eigen::Vector3d& foot, double ground_z, double voxel) {
  constexpr int kPoints = 32;
  std::vector<cv::Point> line;
  for (int k = 0; k <= kPoints; ++k) {
    const Eigen::Vector3d point(foot.x(), foot.y(), ground_z + (foot.z() + voxel - ground_z) * k / kPoints);
    Eigen::Vector2d pixel;
    if (!view.WorldToPixel(point, &pixel)) return {};
    line.emplace_back(int(std::floor(pixel.x())), int(std::floor(pixel.y())));
  }
  cv::Mat drawn = cv::Mat::zeros(view.camera.height, view.camera.width, CV_8UC1);
  cv::polylines(drawn, line, false, cv::Scalar(255), 1, cv::LINE_8);
  std::vector<cv::Point> pixels;
  cv::findNonZero(drawn, pixels);
  return pixels;
}

// The hull's foot is a voxel's centre of mass, a few pixels beside a thin trunk: the places tried,
// within a voxel and a half of it, in steps of half a voxel.
std::vector<Eigen::Vector3d> FeetNear(const Eigen::Vector3d& foot, double voxel) {
  std::vector<Eigen::Vector3d> feet;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) feet.push_back(foot + Eigen::Vector3d(dx, dy, 0) * voxel / 2);
  return feet;
}

// What a stretch's centre line shows in one photo.
struct StretchEvidence {
  int pixels = 0, held = 0, known = 0, in_front = 0;
};

StretchEvidence Evidence(const Image8& photo, const Image8& matte, const std::vector<cv::Point>& line,
                         const CleanPlate& plate, const TrunkFootOptions& options) {
  StretchEvidence evidence;
  for (const cv::Point& p : line) {
    ++evidence.pixels;
    evidence.held += matte.at(p.x, p.y) >= 128;
    if (!plate.Known(p.x, p.y)) continue;
    ++evidence.known;
    double difference = 0;
    for (int c = 0; c < 3; ++c)
      difference += std::abs(photo.at(p.x, p.y, c) / 255.0 - plate.colour.at(p.x, p.y, c)) / 3;
    evidence.in_front += difference >= options.unlike;
  }
  return evidence;
}

// Whether the stretch stands in front of the ground in this photo and its matte misses it.
bool StandsAndIsMissed(const StretchEvidence& evidence, const TrunkFootOptions& options) {
  return evidence.pixels > 0 && evidence.held <= options.max_held * evidence.pixels &&
         evidence.known >= options.min_known * evidence.pixels &&
         evidence.in_front >= options.min_in_front * evidence.known;
}

// The centre line known tree, a band of `half_width` pixels around it solved, the rest of the
// matte kept.
void MendStretch(const cv::Mat& rgb, const std::vector<cv::Point>& line, int half_width,
                 const MatteOptions& matte_options, cv::Mat& alpha) {
  cv::Mat centre = cv::Mat::zeros(alpha.size(), CV_8UC1), band;
  for (const cv::Point& p : line) centre.at<uint8_t>(p) = 255;
  cv::dilate(centre, band, matte::Disc(half_width));
  matte::SolveAgainInside(rgb, band, centre, cv::Mat(), matte_options, alpha);
}

// Two voxels either side of the centre line at the foot, in pixels of this photo: the foot found
// is within a quarter of a voxel of the trunk's axis, and a trunk is often wider than a voxel (the young
// oak's test: recall of the foot 0.498 with one voxel, 0.929 with two).
int HalfWidth(const View& view, const Eigen::Vector3d& foot, double voxel) {
  const double depth = view.pose.ToCamera(foot).z();
  return std::max(2, int(std::ceil(2 * view.camera.FocalX() * voxel / std::max(depth, 1e-9))));
}

}  // namespace

std::vector<std::string> CarryTrunkToGround(const std::vector<View>& views, const std::vector<Image8>& photos,
                                            const MatteOptions& matte_options, const CleanPlateOptions& plate_options,
                                            const TrunkFootOptions& options, std::vector<Image8>& mattes) {
  options.Check();
  if (views.size() != photos.size() || views.size() != mattes.size())
    Fail("carrying the trunk to the ground needs one photo and one matte per view");
  VisualHull hull;
  try {
    hull = CarveVisualHullAuto(views, mattes, options.hull);
  } catch (const Error&) {
    return {};  // no hull: the guard that follows says why
  }
  const double height = hull.bounds_max.z() - options.ground_z;
  if (!(height > 0) || hull.base.z() - options.ground_z < options.min_lift * height) return {};
  // Judged on the mattes as they stand: no photo's carried trunk hides another's ground.
  const std::vector<Image8> before = mattes;
  const std::vector<Eigen::Vector3d> feet = FeetNear(hull.base, hull.voxel_size);
  // Every photo's lines through the feet tried, and the plate along all of them.
  std::vector<std::vector<std::vector<cv::Point>>> lines(views.size());
  std::vector<CleanPlate> plates(views.size());
  tbb::parallel_for(size_t(0), views.size(), [&](size_t i) {
    Image8 region(views[i].camera.width, views[i].camera.height, 1, 0);
    for (const Eigen::Vector3d& foot : feet) {
      lines[i].push_back(StretchPixels(views[i], foot, options.ground_z, hull.voxel_size));
      for (const cv::Point& p : lines[i].back()) region.at(p.x, p.y) = 255;
    }
    plates[i] = GroundCleanPlate(views, photos, before, i, region, plate_options);
  });
  // The trunk stands where the most pixels stand in front of the ground, over all photos.
  size_t best = 0;
  long most = -1;
  for (size_t k = 0; k < feet.size(); ++k) {
    long in_front = 0;
    for (size_t i = 0; i < views.size(); ++i)
      in_front += Evidence(photos[i], before[i], lines[i][k], plates[i], options).in_front;
    if (in_front > most) best = k, most = in_front;
  }
  std::vector<uint8_t> carried(views.size(), 0);
  tbb::parallel_for(size_t(0), views.size(), [&](size_t i) {
    const StretchEvidence evidence = Evidence(photos[i], mattes[i], lines[i][best], plates[i], options);
    if (lines[i][best].empty() || !StandsAndIsMissed(evidence, options)) return;
    cv::Mat alpha = matte::View(mattes[i]);  // shares the matte's pixels
    MendStretch(matte::View(photos[i]), lines[i][best], HalfWidth(views[i], feet[best], hull.voxel_size), matte_options,
                alpha);
    carried[i] = 1;
  });
  std::vector<std::string> names;
  for (size_t i = 0; i < views.size(); ++i)
    if (carried[i]) names.push_back(views[i].name);
  return names;
}

}  // namespace voltree
