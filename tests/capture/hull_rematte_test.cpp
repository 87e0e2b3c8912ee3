// Re-matting inside the visual hull of the photos that agree, on a studio set photographed from
// 20 degrees in front of the realistic backdrop (ground behind the tree in every photo, the
// skyline at the top of the lower ring's photos), with the true cameras. Half of the lower ring's
// first mattes are what per-photo matting gave there on the third-party aspen: the skyline taken
// for the tree, and the tree, against the ground, missed. Nothing of those mattes seeds the tree.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "capture/colmap_binary.h"
#include "capture/matte/hull_refine.h"
#include "capture/matte/metrics.h"
#include "core/colmap_model.h"
#include "core/error.h"
#include "core/image.h"
#include "capture/young_oak_photos.h"
#include "expect_check_names.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

// Every other photo of the lower ring (the studio names that ring's photos first).
bool EveryOtherLowerRingPhoto(size_t i, size_t count) { return i < count / 2 && i % 2 == 1; }

// The skyline band across the top eighth of the photo, and nothing of the tree.
Image8 SkylineOnly(const Image8& truth) {
  Image8 matte(truth.width, truth.height, 1);
  for (int y = 0; y < truth.height / 8; ++y)
    for (int x = 0; x < truth.width; ++x) matte.at(x, y) = 255;
  return matte;
}

bool LeafGreen(const Image8& photo, int x, int y) {
  const int r = photo.at(x, y, 0), g = photo.at(x, y, 1), b = photo.at(x, y, 2);
  return g > r + 8 && g > b + 8;
}

// The aspen's eye-level photos show a grey trunk against grey soil: `photo` with every pixel of
// the tree that is not leaf green painted that grey.
Image8 WithGreyBark(Image8 photo, const Image8& truth) {
  for (int y = 0; y < truth.height; ++y)
    for (int x = 0; x < truth.width; ++x)
      if (truth.at(x, y) > 127 && !LeafGreen(photo, x, y))
        for (int c = 0; c < 3; ++c) photo.at(x, y, c) = uint8_t(c == 2 ? 150 : 140);
  return photo;
}

// The row a third of the tree's height above its lowest pixel in `matte`: below it, the trunk.
int TrunkRow(const Image8& matte) {
  int top = matte.height, bottom = 0;
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x)
      if (matte.at(x, y) > 127) top = std::min(top, y), bottom = std::max(bottom, y);
  return bottom - (bottom - top) / 3;
}

// The mend alone: every photo trusted, no guard's passes.
HullRematteOptions MendAlone() {
  HullRematteOptions options;
  options.max_carve_fraction = 0.99;
  options.max_keep_ratio = 1e6;
  options.guard_passes = 0;
  // A narrow part must be twice the radius long: the young oak's trunk below the crown is
  // shorter than the aspen's.
  options.narrow_radius_bands = 5;
  // Carried down to the ground from the hull's foot, the trunk comes back without any mend
  // (recall 0.497 inside the usual hull alone): trunk_foot_test.cpp measures that.
  options.carry_trunk_to_ground = false;
  return options;
}

class HullRematte : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    test::YoungOakPhotos set = test::PhotographYoungOak("--min-elevation 20");  // two rings, at 20 and 35 degrees
    ASSERT_FALSE(set.views.empty());
    views_ = std::move(set.views);
    photos_ = std::move(set.photos);
    truth_ = std::move(set.truth);
  }

  static bool Missed(size_t i) { return EveryOtherLowerRingPhoto(i, views_.size()); }

  static inline std::vector<View> views_;
  static inline std::vector<Image8> photos_, truth_;
};

// Measured: 12 of 16 photos trusted; the missed photos come back at MSE 0.0074 mean, 0.0094 worst
// (recall of the tree 0.982). Seeded by the eroded core of the hull's projection instead, as
// before, they came back at 0.0254 mean, 0.0293 worst: the hull's loose projection, taken as the
// first estimate, fills the gaps of the crown.
TEST_F(HullRematte, FindsTheTreeWhereTheFirstMatteMissedItEntirely) {
  std::vector<Image8> mattes;
  for (size_t i = 0; i < views_.size(); ++i) mattes.push_back(Missed(i) ? SkylineOnly(truth_[i]) : truth_[i]);
  const HullRematteResult result = RematteFromHull(views_, photos_, mattes, HullRematteOptions{});
  double mean = 0, worst = 0, recall = 0;
  size_t missed = 0;
  for (size_t i = 0; i < views_.size(); ++i) {
    if (!Missed(i)) continue;
    const MatteError error = CompareMattes(mattes[i], truth_[i]);
    mean += error.mse / 1000;
    worst = std::max(worst, error.mse / 1000);
    double tree = 0, found = 0;
    for (size_t p = 0; p < truth_[i].pixels.size(); ++p)
      if (truth_[i].pixels[p] > 127) {
        ++tree;
        found += mattes[i].pixels[p] > 127;
      }
    recall += found / tree;
    ++missed;
  }
  mean /= double(missed);
  recall /= double(missed);
  std::printf("%zu trusted, majority hull %d; missed photos re-matted: MSE %.4f mean, %.4f worst, recall %.3f\n",
              result.trusted.size(), int(result.majority_hull), mean, worst, recall);
  EXPECT_LT(mean, 0.015);
  EXPECT_LT(worst, 0.02);
  EXPECT_GT(recall, 0.9);
}

// The aspen's eye-level photos: a grey trunk against grey soil, and first mattes that took the
// skyline for the tree (so the photo is not trusted) and found the leaves but no bark, so nothing
// of the trunk's colour seeds the solver. Here the bark of every photo is painted that grey, and
// the photos' first mattes keep only the leaves. The trunk's recall below the crown (the lowest
// third of the tree), with and without the narrow parts of the hull seeded by GrabCut, and
// without the later mending of a matte that misses a narrow part (narrow_parts_test.cpp).
// Measured: 0.802 with, 0.476 without; 0.918 at the defaults.
TEST_F(HullRematte, FindsTheTrunkTheFirstMatteCutOff) {
  std::vector<int> trunk_row(views_.size(), 0);
  std::vector<Image8> first, photos = photos_;
  for (size_t i = 0; i < views_.size(); ++i) {
    Image8 matte = truth_[i];
    photos[i] = WithGreyBark(photos[i], truth_[i]);
    if (Missed(i)) {
      trunk_row[i] = TrunkRow(matte);
      for (int y = 0; y < matte.height; ++y)
        for (int x = 0; x < matte.width; ++x)
          matte.at(x, y) = y < matte.height / 8 ? 255 : LeafGreen(photos[i], x, y) ? matte.at(x, y) : 0;
    }
    first.push_back(std::move(matte));
  }
  // The seeding alone: the later passes change the trunk too (the mending brings it back, the
  // mixed pixels lower the alpha of grey bark against grey soil), and are measured with defaults.
  auto trunk_recall = [&](bool seed_narrow_parts, bool later_passes) {
    HullRematteOptions options;
    options.seed_narrow_parts = seed_narrow_parts;
    options.mend_narrow_parts = later_passes;
    options.matte_mixed_pixels = later_passes;
    std::vector<Image8> mattes = first;
    RematteFromHull(views_, photos, mattes, options);
    double trunk = 0, found = 0;
    for (size_t i = 0; i < views_.size(); ++i)
      for (int y = Missed(i) ? trunk_row[i] : truth_[i].height; y < truth_[i].height; ++y)
        for (int x = 0; x < truth_[i].width; ++x)
          if (truth_[i].at(x, y) > 127) {
            ++trunk;
            found += mattes[i].at(x, y) > 127;
          }
    return found / std::max(trunk, 1.0);
  };
  const double with = trunk_recall(true, false), without = trunk_recall(false, false);
  const double defaults = trunk_recall(true, true);
  std::printf("trunk below the cut: recall %.3f with the narrow parts seeded, %.3f without; %.3f at the defaults\n",
              with, without, defaults);
  EXPECT_GT(with, 0.7);
  EXPECT_GT(with, without + 0.2);
  EXPECT_GT(defaults, 0.7);
}

// More eye-level photos miss the trunk than the usual hull lets be outvoted: on the aspen at 20°,
// 3 of 12 after the first pass, then 9 of 12 once the photos matted again inside that hull had
// lost it too. Here the mattes are true but for the trunk below the crown, cut off in half of
// the lower ring's photos (4 of 16), and every photo is trusted and none matted again, so only
// the mend can bring the trunk back. At 384²: at 192² the trunk is too short to be a narrow part.
// The trunk's recall in those photos. Measured: 0.145, 2 photos mended, with the majority's hull;
// 0.000, none mended, inside the usual hull alone (it carves the trunk). The young oak's hull is
// coarse around a short trunk, so only part of it comes back; on the aspen, whose trunk is long,
// the bench measures what it is worth (README, Capture).
TEST(HullRematteTrunk, MendsATrunkThatSeveralPhotosMissed) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("--min-elevation 20", 384);
  ASSERT_FALSE(set.views.empty());
  const size_t count = set.views.size();
  const auto cut = [&](size_t i) { return i < count / 2 && i % 2 == 0; };
  std::vector<int> trunk_row(count, 0);
  std::vector<Image8> mattes;
  for (size_t i = 0; i < count; ++i) {
    Image8 matte = set.truth[i];
    if (cut(i)) {
      trunk_row[i] = TrunkRow(matte);
      for (int y = trunk_row[i]; y < matte.height; ++y)
        for (int x = 0; x < matte.width; ++x) matte.at(x, y) = 0;
    }
    mattes.push_back(std::move(matte));
  }
  HullRematteOptions options = MendAlone();
  auto trunk_recall = [&](bool majority, size_t* mended) {
    options.mend_inside_majority_hull = majority;
    std::vector<Image8> mended_mattes = mattes;
    *mended = RematteFromHull(set.views, set.photos, mended_mattes, options).mended.size();
    double trunk = 0, found = 0;
    for (size_t i = 0; i < count; ++i) {
      if (!cut(i)) continue;
      for (int y = trunk_row[i]; y < set.truth[i].height; ++y)
        for (int x = 0; x < set.truth[i].width; ++x)
          if (set.truth[i].at(x, y) > 127) {
            ++trunk;
            found += mended_mattes[i].at(x, y) > 127;
          }
    }
    return found / std::max(trunk, 1.0);
  };
  size_t mended = 0, mended_before = 0;
  const double recall = trunk_recall(true, &mended), before = trunk_recall(false, &mended_before);
  std::printf(
      "the trunk below the crown in the photos that missed it: recall %.3f, %zu mended (%.3f, %zu mended "
      "inside the hull that lets a few photos be outvoted)\n",
      recall, mended, before, mended_before);
  EXPECT_GE(mended, 2u);
  EXPECT_EQ(mended_before, 0u);
  EXPECT_GT(recall, before + 0.1);
}

// The ground behind a trunk, painted on that trunk: what the aspen's eye-level photo showed, a grey
// trunk in front of a grey-green bush of its colour. Each pixel of the trunk below `row` in photo
// `target` takes 90 % of the colour the nearest other photo shows where the pixel's ray meets the
// ground (at 80 % parallax no longer explains it).
void CamouflageTrunk(const std::vector<View>& views, const std::vector<Image8>& photos, const Image8& truth,
                     size_t target, int row, Image8& photo) {
  size_t nearest = target == 0 ? 1 : 0;
  const Eigen::Vector3d center = views[target].pose.Center();
  for (size_t i = 0; i < views.size(); ++i)
    if (i != target && (views[i].pose.Center() - center).norm() < (views[nearest].pose.Center() - center).norm())
      nearest = i;
  const View& other = views[nearest];
  for (int y = row; y < truth.height; ++y)
    for (int x = 0; x < truth.width; ++x) {
      if (truth.at(x, y) <= 127) continue;
      const Eigen::Vector3d ray = views[target].PixelRay({x + 0.5, y + 0.5});
      if (ray.z() >= 0) continue;
      const Eigen::Vector3d ground = center - center.z() / ray.z() * ray;
      const Eigen::Vector2d at = other.camera.Project(other.pose.ToCamera(ground));
      const int u = int(std::floor(at.x())), v = int(std::floor(at.y()));
      if (u < 0 || v < 0 || u >= photos[nearest].width || v >= photos[nearest].height) continue;
      for (int c = 0; c < 3; ++c)
        photo.at(x, y, c) = uint8_t(std::lround(0.9 * photos[nearest].at(u, v, c) + 0.1 * photo.at(x, y, c)));
    }
}

// One lower-ring photo whose trunk shows almost the very ground behind it and whose first matte
// missed that trunk: the ground hypothesis of parallax explains the trunk as ground, and the mend,
// which counts known background as no miss, left the trunk out (and the reconstruction carves
// what a matte leaves under 5/255 out of every view). Spared along the narrow parts' centre lines,
// the trunk is mended; the photo's colours barely tell it, so only part of it comes back.
// Measured, the share of the trunk kept above 5/255: 0.103 spared, 0.000 claimed (0.231 both at
// 80 %, where parallax does not claim it).
TEST(HullRematteTrunk, ParallaxDoesNotClaimATrunkInFrontOfGroundOfItsColour) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("--min-elevation 20", 384);
  ASSERT_FALSE(set.views.empty());
  const size_t target = 2;  // on the lower ring (the studio names that ring's photos first)
  const int row = TrunkRow(set.truth[target]);
  std::vector<Image8> photos = set.photos, mattes = set.truth;
  CamouflageTrunk(set.views, set.photos, set.truth[target], target, row, photos[target]);
  for (int y = row; y < mattes[target].height; ++y)
    for (int x = 0; x < mattes[target].width; ++x) mattes[target].at(x, y) = 0;
  HullRematteOptions options = MendAlone();
  auto trunk_recall = [&](bool spared, bool* mended) {
    options.parallax_spares_narrow_parts = spared;
    std::vector<Image8> result = mattes;
    *mended = !RematteFromHull(set.views, photos, result, options).mended.empty();
    double trunk = 0, found = 0;
    for (int y = row; y < set.truth[target].height; ++y)
      for (int x = 0; x < set.truth[target].width; ++x)
        if (set.truth[target].at(x, y) > 127) {
          ++trunk;
          found += result[target].at(x, y) > 5;
        }
    return found / std::max(trunk, 1.0);
  };
  bool mended_spared = false, mended_claimed = true;
  const double spared = trunk_recall(true, &mended_spared), claimed = trunk_recall(false, &mended_claimed);
  std::printf("the camouflaged trunk kept (alpha > 5/255): %.3f spared from parallax, %.3f claimed by it\n", spared,
              claimed);
  EXPECT_TRUE(mended_spared);
  EXPECT_FALSE(mended_claimed);
  EXPECT_GT(spared, claimed + 0.05);
}

// The eye-level ring of the default rings sees sky behind the upper crown (the plain backdrop:
// nothing but sky there). Its photos, not trusted (their first mattes hold a skyline band
// alone), are matted again inside the hull; the sky the photo's own colour model explains stays
// background there, where the solver alone blurred the crown's gaps into it; and the last pass,
// which mattes every photo once more where the colour of a leaf only in part of its pixel tells
// it from the known sky (mixed_pixels.h), clears most of what is left. The alpha re-matting puts
// on the truth's background in the photos' upper half, in fully opaque pixels' worth per
// re-matted photo at 192². Measured: 212 solved, 164 kept clear, 74 with the mixed pixels
// matted again (the realistic backdrop, with hills and trees behind much of the crown: 289 and
// 282 without the last pass).
TEST(HullRematteSky, KeepsTheClearSkyInTheCrownsGapsBackground) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("--backdrop plain");  // rings at 5 and 35 degrees
  ASSERT_FALSE(set.views.empty());
  const std::vector<View>& views = set.views;
  const std::vector<Image8>& truth = set.truth;
  const auto untrusted = [&](size_t i) { return EveryOtherLowerRingPhoto(i, views.size()); };
  std::vector<Image8> first;
  for (size_t i = 0; i < views.size(); ++i) first.push_back(untrusted(i) ? SkylineOnly(truth[i]) : truth[i]);
  auto false_alpha_in_the_sky = [&](bool keep_clear_sky, bool matte_mixed_pixels) {
    HullRematteOptions options;
    options.keep_clear_sky = keep_clear_sky;
    options.matte_mixed_pixels = matte_mixed_pixels;
    std::vector<Image8> mattes = first;
    RematteFromHull(views, set.photos, mattes, options);
    double sum = 0;
    int photos_counted = 0;
    for (size_t i = 0; i < views.size(); ++i) {
      if (!untrusted(i)) continue;
      ++photos_counted;
      // The upper half of the photo: the crown, with the sky behind it at this ring.
      for (int y = 0; y < truth[i].height / 2; ++y)
        for (int x = 0; x < truth[i].width; ++x)
          if (truth[i].at(x, y) == 0) sum += mattes[i].at(x, y) / 255.0;
    }
    return sum / std::max(photos_counted, 1);
  };
  const double solved = false_alpha_in_the_sky(false, false), kept_clear = false_alpha_in_the_sky(true, false),
               mixed_solved = false_alpha_in_the_sky(true, true);
  std::printf(
      "alpha on the sky behind the crown, per re-matted photo: %.1f solved, %.1f kept clear, %.1f with the "
      "mixed pixels matted again\n",
      solved, kept_clear, mixed_solved);
  EXPECT_LT(kept_clear, 0.85 * solved);
  EXPECT_LT(mixed_solved, 0.7 * kept_clear);
}

TEST(HullRematteOptions, CheckNamesTheNarrowPartsFields) {
  HullRematteOptions zero_radius;
  zero_radius.narrow_radius_bands = 0;
  testing::ExpectCheckNames(zero_radius, "HullRematteOptions.narrow_radius_bands");
  HullRematteOptions missed_all;
  missed_all.max_missed_narrow = 1;
  testing::ExpectCheckNames(missed_all, "HullRematteOptions.max_missed_narrow");
}

}  // namespace
}  // namespace voltree
