// The studio's layers obey photo = foreground over background and matte = foreground alpha.
#include "samples/studio_layers.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "samples/studio_renderer.h"
#include "samples/studio_rig.h"
#include "studio_test_mesh.h"

namespace voltree {
namespace {

TEST(StudioLayers, PhotoIsForegroundOverBackground) {
  const TreeMesh mesh = testing::MakeToyTree();
  StudioOptions options;
  options.width = 96;
  options.height = 96;
  options.views = 2;
  options.rings = 1;
  options.held_out = 0;
  StudioRenderer renderer(mesh, options);
  const auto [lo, hi] = mesh.Bounds();
  const StudioRig rig = MakeStudioRig(lo.cast<double>(), hi.cast<double>(), options);
  for (const View& view : rig.inputs) {
    const StudioLayers layers = renderer.Photograph(view);
    int opaque = 0, fractional = 0, worst = 0;
    for (int y = 0; y < 96; ++y)
      for (int x = 0; x < 96; ++x) {
        const int alpha = layers.foreground.at(x, y, 3);
        ASSERT_EQ(layers.matte.at(x, y), alpha);
        opaque += alpha == 255;
        fractional += alpha > 0 && alpha < 255;
        for (int c = 0; c < 3; ++c) {
          const int foreground = layers.foreground.at(x, y, c);
          ASSERT_LE(foreground, alpha) << "premultiplied colour exceeds alpha";
          const double over = foreground + (255 - alpha) * layers.background.at(x, y, c) / 255.0;
          const int error = static_cast<int>(std::abs(layers.photo.at(x, y, c) - over) + 0.5);
          worst = std::max(worst, error);
          if (alpha == 255) {
            ASSERT_EQ(layers.photo.at(x, y, c), foreground);
          }
          if (alpha == 0) {
            ASSERT_EQ(layers.photo.at(x, y, c), layers.background.at(x, y, c));
          }
        }
      }
    EXPECT_LE(worst, 1);
    // The toy tree covers a few hundred pixels at 96x96; 4x4 supersampling gives soft edges.
    EXPECT_GT(opaque, 100);
    EXPECT_GT(fractional, 50);
  }
}

TEST(StudioLayers, ComposeFromKnownValues) {
  ImageF tree(2, 1, 4), backdrop(2, 1, 4);
  // Pixel 0: half covered by linear 0.2 grey (premultiplied 0.1). Pixel 1: empty.
  for (int c = 0; c < 3; ++c) {
    tree.at(0, 0, c) = 0.1f;
    backdrop.at(0, 0, c) = 1.0f;
    backdrop.at(1, 0, c) = 0.0f;
  }
  tree.at(0, 0, 3) = 0.5f;
  const StudioLayers layers = ComposeStudioLayers(tree, backdrop);
  EXPECT_EQ(layers.matte.at(0, 0), 128);
  // sRGB(0.2) = 0.4845 -> 0.4845 * 128 = 62.0
  EXPECT_EQ(layers.foreground.at(0, 0, 0), 62);
  EXPECT_EQ(layers.photo.at(0, 0, 0), 62 + 127);
  EXPECT_EQ(layers.matte.at(1, 0), 0);
  EXPECT_EQ(layers.photo.at(1, 0, 1), 0);
}

}  // namespace
}  // namespace voltree
