// Background told by parallax on a studio set photographed in front of the realistic backdrop,
// with the true cameras: how much of the true background a neighbouring photo explains, and how
// little of the tree. The tree's own matte in the neighbour is what keeps leaves seen from above
// from matching the leaves that hide the same ground in the next photo.
#include <gtest/gtest.h>
#include <algorithm>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "capture/colmap_binary.h"
#include "capture/matte/backdrop.h"
#include "capture/matte/consistency.h"
#include "core/colmap_model.h"
#include "core/error.h"
#include "core/image.h"
#include "pipeline/voltree_binary.h"
#include "expect_check_names.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

struct StudioSet {
  std::vector<View> views;
  std::vector<Image8> photos, mattes;
};

class Backdrop : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(::testing::TempDir()) / Str("voltree_backdrop_", ::getpid());
    fs::remove_all(dir_);
    // 16 photos in two rings (45 degrees apart within a ring) at 192²; about a second.
    ASSERT_EQ(test::Voltree("synth --tree young-oak --views 16 --held-out 0 --size 192 --quiet -o " + dir_.string()),
              0);
    set_.views = ReadColmapModel(dir_ / "sparse").Views();
    for (const View& view : set_.views) {
      set_.photos.push_back(ReadImage8(dir_ / "images" / view.name, 3));
      set_.mattes.push_back(ReadImage8(dir_ / "mattes" / (fs::path(view.name).stem().string() + ".png"), 1));
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // Over all photos: the share of the true background explained, and of the tree (alpha > 0.5).
  static std::pair<double, double> ExplainedShares(const std::vector<Image8>& mattes) {
    double background = 0, background_explained = 0, tree = 0, tree_explained = 0;
    for (size_t i = 0; i < set_.views.size(); ++i) {
      const Image8 explained = ExplainedByBackdrop(set_.views, set_.photos, mattes, i, BackdropOptions{});
      const Image8& truth = set_.mattes[i];
      for (size_t p = 0; p < truth.pixels.size(); ++p) {
        const bool on_tree = truth.pixels[p] > 127, is_explained = explained.pixels[p] != 0;
        if (truth.pixels[p] == 0) {
          ++background;
          background_explained += is_explained;
        } else if (on_tree) {
          ++tree;
          tree_explained += is_explained;
        }
      }
    }
    return {background_explained / background, tree_explained / tree};
  }

  static inline fs::path dir_;
  static inline StudioSet set_;
};

// Measured: 0.573 of the background explained (the rest is the clutter, the hills and distant trees,
// and ground a neighbour does not see), 0.0003 of the tree.
TEST_F(Backdrop, ExplainsTheBackgroundAndNotTheTree) {
  const auto [background, tree] = ExplainedShares(set_.mattes);
  std::printf("explained: background %.3f, tree %.4f\n", background, tree);
  EXPECT_GT(background, 0.5);
  EXPECT_LT(tree, 0.003);
}

// Without the neighbours' mattes the crown seen from above matches the crown that hides the same
// ground in the next photo. Measured: 0.0009 of the tree explained, three times as much as with
// them (on the oak at 512², seen from the upper ring, whole patches of crown: matte MSE 0.0048
// with the neighbours' mattes, 0.0115 without).
TEST_F(Backdrop, TheNeighboursTreeHidesItsGround) {
  const auto [background, tree] = ExplainedShares({});
  const auto [background_with, tree_with] = ExplainedShares(set_.mattes);
  std::printf("tree explained without the neighbours' mattes %.4f, with %.4f\n", tree, tree_with);
  EXPECT_GT(tree, 2 * tree_with);
  EXPECT_GT(background, background_with - 0.01);
}

// Behind the hull, near the tree where matting is hard: distant trees, bushes and hills the far
// and ground hypotheses leave. The hull is carved from the true mattes; the pixels asked are
// those near its projection that neither hypothesis explained.
struct BehindShares {
  double background = 0, tree = 0;
};
BehindShares ExplainedBehindShares(const StudioSet& set, const BackdropOptions& options) {
  const std::vector<bool> all(set.views.size(), true);
  const std::vector<HullProjection> hulls =
      ProjectHull(set.views, set.mattes, all, set.views, MatteConsistencyOptions{});
  double background = 0, background_explained = 0, tree = 0, tree_explained = 0;
  for (size_t i = 0; i < set.views.size(); ++i) {
    const Image8 backdrop = ExplainedByBackdrop(set.views, set.photos, set.mattes, i, options);
    Image8 region = hulls[i].mask;
    const int w = region.width, h = region.height;
    for (int y = 0; y < h; ++y)  // the hull grown by 2 pixels, as re-matting grows it
      for (int x = 0; x < w; ++x)
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int sx = std::clamp(x + dx, 0, w - 1), sy = std::clamp(y + dy, 0, h - 1);
            if (hulls[i].mask.pixels[size_t(sy) * w + sx] != 0) region.pixels[size_t(y) * w + x] = 255;
          }
    for (size_t p = 0; p < region.pixels.size(); ++p)
      if (backdrop.pixels[p] != 0) region.pixels[p] = 0;
    const Image8 behind = ExplainedBehindHull(set.views, set.photos, hulls, i, region, options);
    const Image8& truth = set.mattes[i];
    for (size_t p = 0; p < truth.pixels.size(); ++p) {
      if (region.pixels[p] == 0) continue;
      if (truth.pixels[p] == 0) {
        ++background;
        background_explained += behind.pixels[p] != 0;
      } else if (truth.pixels[p] > 127) {
        ++tree;
        tree_explained += behind.pixels[p] != 0;
      }
    }
  }
  return {background_explained / std::max(background, 1.0), tree_explained / std::max(tree, 1.0)};
}

// Measured: 0.156 of that background explained, none of the tree (with one neighbour's word
// instead of two: 0.370 and still none here, but the aspen's thin trunk was lost that way).
TEST_F(Backdrop, BehindTheHullExplainsTheClutterAndNotTheTree) {
  const BehindShares shares = ExplainedBehindShares(set_, BackdropOptions{});
  std::printf("behind the hull: background %.3f, tree %.4f\n", shares.background, shares.tree);
  EXPECT_GT(shares.background, 0.1);
  EXPECT_LT(shares.tree, 0.002);
}

TEST(BackdropOptions, CheckNamesTheField) {
  BackdropOptions options;
  options.max_difference = 0;
  testing::ExpectCheckNames(options, "BackdropOptions.max_difference");
}

}  // namespace
}  // namespace voltree
