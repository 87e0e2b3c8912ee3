// The CPU's copy of the renderer's image formation on volumes made by hand, where the expected
// pixels can be worked out on paper.
#include <gtest/gtest.h>

#include "reconstruct/billboard_raster.h"
#include "reconstruct/billboards.h"

namespace voltree {
namespace {

// A camera on the -Y side of the unit cube looking at its centre along +Y, 64 x 64 pixels, the
// cube's front face 40 pixels wide.
View FrontCamera() {
  View view;
  view.name = "front.png";
  view.camera = Camera::Pinhole(64, 64, 100, 100, 32, 32);
  view.pose = Pose::LookAt(Eigen::Vector3d(0.5, -2.0, 0.5), Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d::UnitZ());
  return view;
}

// Two levels over the unit cube: the root, and two cells one behind the other along the view
// (y = 0 near, y = 1 far). Each cell's billboard for `view` has uniform texels.
Volume TwoCellsInDepth(const View& view, std::array<uint8_t, 4> near, std::array<uint8_t, 4> far) {
  Volume volume;
  volume.texels = 2;
  volume.views = {MakeVolumeView(view)};
  VolumeLevel root;
  root.resolution = 1;
  root.cells = {{0, 0, 0}};
  root.density = {1};
  VolumeLevel children;
  children.resolution = 2;
  children.cells = {{0, 0, 0}, {0, 1, 0}};  // sorted by (z, y, x): near (y = 0) first
  children.density = {1, 1};
  for (uint32_t c = 0; c < 2; ++c) {
    children.billboards.push_back({c, 0});
    for (int t = 0; t < 4; ++t)
      children.texels.insert(children.texels.end(), (c == 0 ? near : far).begin(), (c == 0 ? near : far).end());
  }
  volume.levels = {root, children};
  return volume;
}

TEST(BillboardRaster, CompositesBackToFrontWithTheOverOperator) {
  const View view = FrontCamera();
  const Volume volume = TwoCellsInDepth(view, {0, 0, 51, 102}, {204, 0, 0, 204});  // premultiplied
  const LayerImage layers = RasterizeLevel(volume, 1, view, ViewBlend{0, -1, 1, 0}, 1.0);
  const ImageF image = CompositeLayers(layers, TexelsAsFloat(volume.levels[1]));
  // Both cells (x in [0, 0.5], z in [0, 0.5]) cover the lower-left quarter of the front face;
  // the near one (depth 2.25) a little more than the far one (depth 2.75). At a pixel inside
  // both: near over far = near + (1 - 0.4) * far.
  const int x = 22, y = 40;  // left of centre, below it (image y grows down, z up)
  ASSERT_EQ(layers.offsets[y * 64 + x + 1] - layers.offsets[y * 64 + x], 2u);
  EXPECT_NEAR(image.at(x, y, 0), 0.6f * 0.8f, 1e-5);
  EXPECT_NEAR(image.at(x, y, 2), 0.2f, 1e-5);
  EXPECT_NEAR(image.at(x, y, 3), 0.4f + 0.6f * 0.8f, 1e-5);
  // Right of the centre nothing is drawn; the far cell's square projects inside the near one's.
  EXPECT_EQ(layers.offsets[y * 64 + 40 + 1] - layers.offsets[y * 64 + 40], 0u);
  EXPECT_EQ(image.at(40, y, 3), 0.0f);
}

TEST(BillboardRaster, BlendsTwoViewsWithTheirWeights) {
  const View view = FrontCamera();
  Volume volume = TwoCellsInDepth(view, {0, 0, 0, 0}, {0, 0, 0, 0});
  volume.levels[1].cells = {{0, 0, 0}};
  volume.levels[1].density = {1};
  volume.views.push_back(volume.views[0]);  // a second view with the same frame
  volume.levels[1].billboards = {{0, 0}, {0, 1}};
  volume.levels[1].texels.assign(2 * 4 * 4, 0);
  for (int t = 0; t < 4; ++t)
    volume.levels[1].texels[t * 4 + 3] = 255, volume.levels[1].texels[16 + t * 4 + 1] = 255,
                                    volume.levels[1].texels[16 + t * 4 + 3] = 255;
  const ImageF image = CompositeLayers(RasterizeLevel(volume, 1, view, ViewBlend{0, 1, 0.75f, 0.25f}, 1.0),
                                       TexelsAsFloat(volume.levels[1]));
  EXPECT_NEAR(image.at(22, 40, 1), 0.25f, 1e-5);  // view 1's green at a quarter
  EXPECT_NEAR(image.at(22, 40, 3), 1.0f, 1e-5);   // both opaque
}

}  // namespace
}  // namespace voltree
