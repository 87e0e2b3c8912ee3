// A matte that misses a trunk the other photos hold, mended where the visual hull of all photos is
// narrow. The young oak from two rings at 20 and 35 degrees in front of the realistic backdrop
// (ground behind the trunk in every photo), 16 photos at 192², the true cameras and mattes; one
// lower-ring photo's trunk below the crown is cut off, as the aspen's eye-level photo had it.
#include <gtest/gtest.h>

#include <algorithm>

#include "capture/matte/consistency.h"
#include "capture/matte/hull_refine.h"
#include "capture/matte/cv.h"
#include "capture/matte/narrow_parts.h"
#include "capture/young_oak_photos.h"

namespace voltree {
namespace {

matte::NarrowPartMend MendAt(const Image8& photo) {
  const int band = std::max(2, std::min(photo.width, photo.height) / 128);  // as the re-matting's
  return {6 * band, band, 0.2};
}

// The trunk below the lowest quarter of the tree; its first row.
int CutTheTrunk(Image8& matte) {
  int top = matte.height, bottom = 0;
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x)
      if (matte.at(x, y) > 127) top = std::min(top, y), bottom = std::max(bottom, y);
  const int row = bottom - (bottom - top) / 4;
  for (int y = row; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) matte.at(x, y) = 0;
  return row;
}

// Measured: the trunk's recall below the cut 0.971 (104 pixels), 0 without; no true matte is mended.
TEST(MendMissedNarrowParts, BringsBackATrunkOneMatteCutOff) {
  const test::YoungOakPhotos set = test::PhotographYoungOak("--min-elevation 20");
  ASSERT_FALSE(set.views.empty());
  const size_t cut = 1;
  std::vector<Image8> mattes = set.truth;
  const int row = CutTheTrunk(mattes[cut]);
  const std::vector<HullProjection> hulls = ProjectHull(set.views, mattes, std::vector<bool>(set.views.size(), true),
                                                        set.views, HullRematteOptions{}.consistency);
  size_t mended_true_mattes = 0;
  for (size_t i = 0; i < set.views.size(); ++i) {
    cv::Mat alpha = matte::View(mattes[i]);
    const bool mended = matte::MendMissedNarrowParts(matte::View(set.photos[i]), matte::View(hulls[i].mask), cv::Mat(),
                                                     MendAt(set.photos[i]), MatteOptions{}, alpha);
    if (i == cut) {
      EXPECT_TRUE(mended);
    } else {
      mended_true_mattes += mended;
    }
  }
  const Image8& truth = set.truth[cut];
  double trunk = 0, found = 0;
  for (int y = row; y < truth.height; ++y)
    for (int x = 0; x < truth.width; ++x)
      if (truth.at(x, y) > 127) {
        ++trunk;
        found += mattes[cut].at(x, y) > 127;
      }
  std::printf("trunk below the cut (%.0f pixels): recall %.3f mended; %zu true mattes mended\n", trunk,
              found / std::max(trunk, 1.0), mended_true_mattes);
  EXPECT_GT(trunk, 20);
  EXPECT_GT(found / std::max(trunk, 1.0), 0.8);
  EXPECT_EQ(mended_true_mattes, 0u);
}

}  // namespace
}  // namespace voltree
