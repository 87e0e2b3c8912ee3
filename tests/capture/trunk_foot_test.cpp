// A trunk whose foot every matte lost, carried down to the ground: the studio's young oak from
// rings at 20° and above, the true cameras, and its true mattes with the lowest stretch of the
// trunk cut out of every one of them, so that every hull ends above the ground.
#include "capture/matte/trunk_foot.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "capture/matte/cv.h"
#include "capture/normalize_hull.h"
#include "capture/young_oak_photos.h"
#include "expect_check_names.h"

namespace voltree {
namespace {

// In each photo, the band of `half_width` pixels around the trunk's axis (the tree frame's z axis)
// from the ground up to `height`: CV_8U, 255 there.
std::vector<cv::Mat> FootBands(const std::vector<View>& views, double height, int half_width) {
  std::vector<cv::Mat> bands;
  for (const View& view : views) {
    cv::Mat band = cv::Mat::zeros(view.camera.height, view.camera.width, CV_8UC1);
    Eigen::Vector2d bottom, top;
    if (view.WorldToPixel(Eigen::Vector3d(0, 0, 0), &bottom) && view.WorldToPixel(Eigen::Vector3d(0, 0, height), &top))
      cv::line(band, cv::Point(int(bottom.x()), int(bottom.y())), cv::Point(int(top.x()), int(top.y())),
               cv::Scalar(255), 2 * half_width + 1);
    bands.push_back(band);
  }
  return bands;
}

class TrunkFootTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    set_ = test::PhotographYoungOak("--min-elevation 20", 384);
    if (set_.views.empty()) return;
    const VisualHull hull = CarveVisualHullAuto(set_.views, set_.truth, HullOptions{});
    // The lowest seventh of the tree: bark alone on the young oak, below its first bough.
    bands_ = FootBands(set_.views, hull.bounds_max.z() / 7, 8);
    for (size_t i = 0; i < set_.views.size(); ++i) {
      Image8 cut = set_.truth[i];
      matte::View(cut).setTo(0, bands_[i]);
      cut_.push_back(cut);
    }
  }
  // The share of the truth's opaque foot (alpha > 0.5 in the bands) that `mattes` hold above 0.5.
  static double FootRecall(const std::vector<Image8>& mattes) {
    double foot = 0, held = 0;
    for (size_t i = 0; i < mattes.size(); ++i) {
      const cv::Mat in_foot = bands_[i] & (matte::View(set_.truth[i]) > 127);
      foot += cv::countNonZero(in_foot);
      held += cv::countNonZero(in_foot & (matte::View(mattes[i]) > 127));
    }
    return held / std::max(foot, 1.0);
  }
  static inline test::YoungOakPhotos set_;
  static inline std::vector<cv::Mat> bands_;
  static inline std::vector<Image8> cut_;
};

// Measured at 384²: the foot's recall 0.000 with the cut mattes, 0.929 after, all 16 photos carried,
// 0.7 pixel's worth of alpha put outside the tree per photo.
TEST_F(TrunkFootTest, CarriesTheTrunkEveryMatteLostDownToTheGround) {
  ASSERT_FALSE(set_.views.empty());
  std::vector<Image8> mattes = cut_;
  const double before = FootRecall(mattes);
  const std::vector<std::string> carried =
      CarryTrunkToGround(set_.views, set_.photos, MatteOptions{}, CleanPlateOptions{}, TrunkFootOptions{}, mattes);
  const double after = FootRecall(mattes);
  double outside = 0;  // alpha put outside the truth's tree
  for (size_t i = 0; i < mattes.size(); ++i)
    for (size_t p = 0; p < mattes[i].pixels.size(); ++p)
      if (set_.truth[i].pixels[p] == 0) outside += mattes[i].pixels[p] / 255.0;
  std::printf(
      "foot recall %.3f before, %.3f after; %zu of %zu photos carried; alpha outside the tree %.1f px per photo\n",
      before, after, carried.size(), mattes.size(), outside / double(mattes.size()));
  EXPECT_LT(before, 0.05);
  EXPECT_GT(after, 0.8);
  EXPECT_GE(carried.size(), 12u);
  EXPECT_LT(outside / double(mattes.size()), 10.0);
}

// With the true mattes the hull reaches the ground (its silhouette cones meet below it): nothing is
// carried, no matte changes.
TEST_F(TrunkFootTest, LeavesATrunkThatReachesTheGround) {
  ASSERT_FALSE(set_.views.empty());
  std::vector<Image8> mattes = set_.truth;
  EXPECT_TRUE(
      CarryTrunkToGround(set_.views, set_.photos, MatteOptions{}, CleanPlateOptions{}, TrunkFootOptions{}, mattes)
          .empty());
  EXPECT_EQ(mattes, set_.truth);
}

TEST(TrunkFootOptions, CheckNamesTheField) {
  const auto with = [](auto set) {
    TrunkFootOptions options;
    set(options);
    return options;
  };
  using testing::ExpectCheckNames;
  ExpectCheckNames(with([](TrunkFootOptions& o) { o.min_lift = -0.1; }), "TrunkFootOptions.min_lift");
  ExpectCheckNames(with([](TrunkFootOptions& o) { o.min_known = 2; }), "TrunkFootOptions.min_known");
  ExpectCheckNames(with([](TrunkFootOptions& o) { o.min_in_front = 1.5; }), "TrunkFootOptions.min_in_front");
  ExpectCheckNames(with([](TrunkFootOptions& o) { o.unlike = 0; }), "TrunkFootOptions.unlike");
  ExpectCheckNames(with([](TrunkFootOptions& o) { o.max_held = -1; }), "TrunkFootOptions.max_held");
}

}  // namespace
}  // namespace voltree
