#include "capture/matte/clean_plate.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "capture/matte/neighbours.h"
#include "core/error.h"

namespace voltree {

void CleanPlateOptions::Check() const {
  if (neighbours < 1 || neighbours > 64)
    FailOption("CleanPlateOptions.neighbours", "must be in [1, 64], got ", neighbours);
  if (min_views < 1 || min_views > neighbours)
    FailOption("CleanPlateOptions.min_views", "must be in [1, neighbours = ", neighbours, "], got ", min_views);
  if (!(agree > 0 && agree < 1)) FailOption("CleanPlateOptions.agree", "must be in (0, 1), got ", agree);
  if (hidden_margin < 0 || hidden_margin > 64)
    FailOption("CleanPlateOptions.hidden_margin", "must be in [0, 64], got ", hidden_margin);
}

namespace matte {
namespace {

// One neighbour's view of the ground behind each pixel of the target: its colour, and whether it
// sees it (on its photo, not hidden by its tree).
struct GroundSample {
  cv::Mat colour;  // CV_32FC3
  cv::Mat seen;    // CV_8U
};

GroundSample SampleGround(const voltree::View& target, const voltree::View& neighbour, const Image8& photo,
                          const Image8& matte, cv::Rect roi, const CleanPlateOptions& options) {
  cv::Mat map_x, map_y;
  DepthMaps(target, neighbour, Depth::kGround, options.ground_z, &map_x, &map_y, roi);
  GroundSample sample;
  cv::remap(ToFloat(photo), sample.colour, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
            cv::Scalar(-10, -10, -10));
  cv::Mat hidden = View(matte) != 0, hidden_here;
  if (options.hidden_margin > 0) cv::dilate(hidden, hidden, Disc(options.hidden_margin));
  cv::remap(hidden, hidden_here, map_x, map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(255));
  sample.seen = (hidden_here == 0) & (map_x >= 0);
  return sample;
}

bool Agree(const cv::Vec3f& a, const cv::Vec3f& b, double agree) {
  return (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2])) / 3 < agree;
}

// The colour that most of `seen` agree with (the first, nearest, among equals: a bush or a rock
// one neighbour sees is outvoted): the mean of those that agree and their RMS distance from it.
// False when fewer than options.min_views agree.
bool AgreedColour(const std::vector<cv::Vec3f>& seen, const CleanPlateOptions& options, cv::Vec3f* colour,
                  float* spread) {
  size_t best = 0;
  int most = 0;
  for (size_t i = 0; i < seen.size(); ++i) {
    int agreeing = 0;
    for (const cv::Vec3f& other : seen) agreeing += Agree(seen[i], other, options.agree);
    if (agreeing > most) best = i, most = agreeing;
  }
  if (most < options.min_views) return false;
  cv::Vec3f mean(0, 0, 0);
  for (const cv::Vec3f& other : seen)
    if (Agree(seen[best], other, options.agree)) mean += other;
  mean /= float(most);
  float square = 0;
  for (const cv::Vec3f& other : seen)
    if (Agree(seen[best], other, options.agree)) square += float(cv::norm(other - mean, cv::NORM_L2SQR));
  *colour = mean;
  *spread = std::sqrt(square / float(most));
  return true;
}

}  // namespace
}  // namespace matte

CleanPlate GroundCleanPlate(const std::vector<View>& views, const std::vector<Image8>& photos,
                            const std::vector<Image8>& mattes, size_t target, const Image8& region,
                            const CleanPlateOptions& options) {
  options.Check();
  if (views.size() != photos.size() || views.size() != mattes.size() || target >= views.size())
    Fail("the clean plate needs one photo and one matte per view (", views.size(), " views, ", photos.size(),
         " photos, ", mattes.size(), " mattes)");
  if (region.width != mattes[target].width || region.height != mattes[target].height)
    Fail("the clean plate's region is ", region.width, "x", region.height, ", its photo ", mattes[target].width, "x",
         mattes[target].height);
  CleanPlate plate{ImageF(region.width, region.height, 3, 0.0f), ImageF(region.width, region.height, 1, -1.0f)};
  // Rays are cast only for the region's pixels: the trunk's foot asks for a few lines.
  const cv::Rect roi = cv::boundingRect(matte::View(region));
  if (roi.empty()) return plate;
  std::vector<matte::GroundSample> samples;
  for (size_t n : matte::NearestViews(views, target, options.neighbours))
    samples.push_back(matte::SampleGround(views[target], views[n], photos[n], mattes[n], roi, options));
  std::vector<cv::Vec3f> seen;
  for (int y = 0; y < region.height; ++y)
    for (int x = 0; x < region.width; ++x) {
      if (region.at(x, y) == 0) continue;
      seen.clear();
      for (const matte::GroundSample& sample : samples)
        if (sample.seen.at<uint8_t>(y, x)) seen.push_back(sample.colour.at<cv::Vec3f>(y, x));
      cv::Vec3f colour;
      float spread;
      if (!matte::AgreedColour(seen, options, &colour, &spread)) continue;
      for (int c = 0; c < 3; ++c) plate.colour.at(x, y, c) = colour[c];
      plate.spread.at(x, y) = spread;
    }
  return plate;
}

}  // namespace voltree
