// A real (llvmpipe) render of a 3-instance scene with a ground plane, from a hand-built asset of
// two levels whose billboards are opaque white squares filling the root cube [-1,1]^2 x [0,2].
#include "render/scene_renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "render/gl_context.h"
#include "render/test_assets.h"

namespace voltree {
namespace {

using test::WhiteAsset;

Scene ThreeTrees(bool with_ground) {
  Scene scene;
  scene.name = "test scene";
  scene.assets = {{"cube", "cube.vtree"}};
  auto add = [&](Eigen::Vector3d position, double rotation, double scale) {
    scene.instances.push_back({0, {position, rotation, scale}});
  };
  add({-6, 0, 0}, 0, 1);
  add({0, 0, 0}, 45, 0.5);  // half as tall: its top is at z = 1
  add({6, 4, 0}, 10, 1.5);
  add({-2.5, 14, -4}, 0, 1);  // buried: wholly below the ground, hidden by it from above
  if (with_ground) scene.ground = SceneGround{Eigen::Vector2d(0, 0), Eigen::Vector2d(60, 60), {0, 0, 255}};
  return scene;
}

View OverTheScene(int size) {
  View view;
  view.camera = Camera::Pinhole(size, size, 0.9 * size, 0.9 * size, 0.5 * size, 0.5 * size);
  view.pose = Pose::LookAt(Eigen::Vector3d(0, -22, 9), Eigen::Vector3d(0, 4, 0), Eigen::Vector3d::UnitZ());
  return view;
}

// Pixels within 2 of `pixel`: whether any is opaque white (a tree: its billboards leave hairline
// seams where cells meet, so one pixel is not enough), or all are the opaque blue ground.
bool IsWhite(const Image8& image, const Eigen::Vector2d& pixel) {
  for (int y = int(pixel.y()) - 2; y <= int(pixel.y()) + 2; ++y)
    for (int x = int(pixel.x()) - 2; x <= int(pixel.x()) + 2; ++x)
      if (image.at(x, y, 3) == 255 && image.at(x, y, 0) > 240 && image.at(x, y, 1) > 240 && image.at(x, y, 2) > 240)
        return true;
  return false;
}
bool IsGround(const Image8& image, const Eigen::Vector2d& pixel) {
  for (int y = int(pixel.y()) - 2; y <= int(pixel.y()) + 2; ++y)
    for (int x = int(pixel.x()) - 2; x <= int(pixel.x()) + 2; ++x)
      if (image.at(x, y, 3) != 255 || image.at(x, y, 0) > 10 || image.at(x, y, 2) < 245) return false;
  return true;
}

TEST(SceneRenderer, InstancesAppearWhereTheyProjectAndTheGroundHidesWhatIsBelowIt) {
  GlContext context;
  constexpr int kSize = 160;
  const View view = OverTheScene(kSize);
  const std::vector<VtreeAsset> assets = {WhiteAsset({.views = 8, .eye_height = 1, .every_fine_cell = true})};
  SceneRenderer renderer(ThreeTrees(true), assets);
  SceneRenderOptions options;
  SceneFrameStats stats;
  const Image8 image = renderer.Render(view, options, &stats);
  EXPECT_EQ(stats.instances_drawn, 4u);
  EXPECT_EQ(stats.instances_culled, 0u);
  auto pixel = [&](const Eigen::Vector3d& world) {
    Eigen::Vector2d p;
    EXPECT_TRUE(view.WorldToPixel(world, &p));
    EXPECT_TRUE(p.x() >= 0 && p.y() >= 0 && p.x() < kSize && p.y() < kSize) << p.transpose();
    return p;
  };
  // Each instance covers the projection of its centre, scaled and moved.
  EXPECT_TRUE(IsWhite(image, pixel({-6, 0, 1})));
  EXPECT_TRUE(IsWhite(image, pixel({0, 0, 0.5})));
  EXPECT_TRUE(IsWhite(image, pixel({6, 4, 1.5})));
  // Scale is honoured: above the half-size cube there is ground, above the 1.5x one there is not.
  EXPECT_TRUE(IsGround(image, pixel({0, 0, 1.9})));
  EXPECT_TRUE(IsWhite(image, pixel({6, 4, 2.8})));
  // Between the trees: ground; the buried cube at (-2.5, 14, -4) is hidden by the ground.
  EXPECT_TRUE(IsGround(image, pixel({-3, 0, 0})));
  EXPECT_TRUE(IsGround(image, pixel({-2.5, 14, -3})));
  // Control: without the ground the buried cube is seen there, and the background is transparent.
  SceneRenderer no_ground(ThreeTrees(false), assets);
  const Image8 bare = no_ground.Render(view, options);
  if (std::getenv("VOLTREE_TEST_IMAGES"))
    WriteImage("/tmp/scene_bare.png", bare), WriteImage("/tmp/scene_ground.png", image);
  EXPECT_TRUE(IsWhite(bare, pixel({-2.5, 14, -3})));
  EXPECT_EQ(bare.at(int(pixel({-3, 0, 0}).x()), int(pixel({-3, 0, 0}).y()), 3), 0);
  EXPECT_GT(stats.trees.billboards, 0u);
  EXPECT_GT(renderer.GpuBytes().Total(), 0u);
}

TEST(SceneRenderer, CullsWhatIsBehindTheCamera) {
  GlContext context;
  const std::vector<VtreeAsset> assets = {WhiteAsset({.views = 8, .eye_height = 1, .every_fine_cell = true})};
  Scene scene = ThreeTrees(true);
  scene.instances.push_back({0, {Eigen::Vector3d(0, -40, 0), 0, 1}});  // behind the eye at y = -22
  SceneRenderer renderer(scene, assets);
  SceneFrameStats stats;
  renderer.Render(OverTheScene(64), {}, &stats);
  EXPECT_EQ(stats.instances_drawn, 4u);
  EXPECT_EQ(stats.instances_culled, 1u);
  SceneRenderOptions no_cull;
  no_cull.cull = false;
  renderer.Render(OverTheScene(64), no_cull, &stats);
  EXPECT_EQ(stats.instances_drawn, 5u);
}

}  // namespace
}  // namespace voltree
