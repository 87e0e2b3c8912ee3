#include "render/tree_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "render/gl_context.h"

namespace voltree {
namespace {

// One DXT5 block: uniform white colour; alpha 255 in texel rows [0, opaque_rows), 0 below.
std::array<uint8_t, 16> Dxt5Block(int opaque_rows) {
  std::array<uint8_t, 16> block{};
  block[0] = 255;  // alpha0
  block[1] = 0;    // alpha1
  uint64_t indices = 0;
  for (int texel = opaque_rows * 4; texel < 16; ++texel) indices |= uint64_t(1) << (3 * texel);  // -> alpha1
  for (int i = 0; i < 6; ++i) block[2 + i] = uint8_t(indices >> (8 * i));
  block[8] = block[9] = block[10] = block[11] = 0xff;  // colour0 = colour1 = white (RGB565)
  return block;                                        // colour indices 0
}

View MakeCamera(const Eigen::Vector3d& eye, int size) {
  View view;
  view.camera = Camera::Pinhole(size, size, 1.2 * size, 1.2 * size, 0.5 * size, 0.5 * size);
  view.pose = Pose::LookAt(eye, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ());
  return view;
}

// Root cube [-1,1]^2 x [0,2], 3 levels, a sparse set of finest cells; every cell has a billboard
// for every view with a white colour tile (0) and an alpha tile (1) opaque in its top half only,
// so the test sees the billboards' orientation, not just their footprint.
struct Scene {
  VtreeAsset asset;
  std::vector<View> cameras;
};
Scene MakeScene(int size) {
  Scene scene;
  VtreeAsset& asset = scene.asset;
  asset.origin = Eigen::Vector3d(-1, -1, 0);
  asset.size = 2;
  asset.texels = 4;
  asset.bounds_min = asset.origin;
  asset.bounds_max = asset.origin + Eigen::Vector3d::Constant(2);
  for (int v = 0; v < 8; ++v) {
    const double azimuth = 2 * std::numbers::pi * v / 8;
    const Eigen::Vector3d eye(5 * std::cos(azimuth), 5 * std::sin(azimuth), 2.5);
    View camera = MakeCamera(eye, size);
    camera.name = "view_" + std::to_string(v) + ".png";
    const Eigen::Matrix3d r = camera.pose.rotation.toRotationMatrix();
    asset.views.push_back({camera.name, eye, r.row(2).transpose(), -r.row(1).transpose()});
    scene.cameras.push_back(camera);
  }
  const std::vector<std::array<uint16_t, 3>> finest = {{0, 0, 0}, {1, 2, 1}, {2, 1, 3},
                                                       {3, 3, 2}, {1, 1, 2}, {2, 2, 0}};
  asset.levels.resize(3);
  for (int l = 0; l < 3; ++l) {
    asset.levels[l].resolution = 1u << l;
    for (const auto& c : finest) {
      const std::array<uint16_t, 3> cell = {uint16_t(c[0] >> (2 - l)), uint16_t(c[1] >> (2 - l)),
                                            uint16_t(c[2] >> (2 - l))};
      if (std::find(asset.levels[l].cells.begin(), asset.levels[l].cells.end(), cell) == asset.levels[l].cells.end())
        asset.levels[l].cells.push_back(cell);
    }
    asset.levels[l].density.assign(asset.levels[l].cells.size(), 1.0f);
    for (uint32_t c = 0; c < asset.levels[l].cells.size(); ++c)
      for (uint16_t v = 0; v < 8; ++v) asset.levels[l].billboards.push_back({c, v, 0, 1});
  }
  asset.atlas.width = 8;
  asset.atlas.height = 4;
  asset.atlas.tile_pitch = 4;
  asset.atlas.tiles_per_row = 2;
  asset.atlas.tile_count = 2;
  for (int opaque_rows : {4, 2}) {
    const auto block = Dxt5Block(opaque_rows);
    asset.atlas.dxt5.insert(asset.atlas.dxt5.end(), block.begin(), block.end());
  }
  return scene;
}

// Where the top half of any level-`level` billboard of view `v` covers a pixel centre (CPU ray casting).
Image8 ExpectedCoverage(const VtreeAsset& asset, int level, int v, const View& camera) {
  const int w = camera.camera.width, h = camera.camera.height;
  Image8 coverage(w, h, 1);
  const VtreeView& view = asset.views[v];
  const Eigen::Vector3d right = view.direction.cross(view.up);
  const double side = asset.size / asset.levels[level].resolution;
  const Eigen::Vector3d eye = camera.pose.Center();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Eigen::Vector3d ray = camera.PixelRay(Eigen::Vector2d(x + 0.5, y + 0.5));
      for (const auto& c : asset.levels[level].cells) {
        const Eigen::Vector3d centre = asset.origin + side * (Eigen::Vector3d(c[0], c[1], c[2]).array() + 0.5).matrix();
        const double t = (centre - eye).dot(view.direction) / ray.dot(view.direction);
        const Eigen::Vector3d local = eye + t * ray - centre;
        const double s = local.dot(right) / side + 0.5, r = 0.5 - local.dot(view.up) / side;
        if (s >= 0 && s <= 1 && r >= 0 && r <= 0.5) coverage.at(x, y) = 255;
      }
    }
  return coverage;
}

TEST(TreeRenderer, InputViewReproducesBillboardAlphaAndOrientation) {
  GlContext context;
  constexpr int kSize = 96;
  const Scene scene = MakeScene(kSize);
  TreeRenderer renderer(scene.asset);
  for (int v : {0, 3}) {
    TreeRenderOptions options;
    options.lod.forced_level = 2;
    FrameStats stats;
    const Image8 image = renderer.Render(scene.cameras[v], options, &stats);
    EXPECT_EQ(stats.views.first, v);
    EXPECT_FLOAT_EQ(stats.views.first_weight, 1.0f);
    EXPECT_EQ(stats.min_level, 2);
    EXPECT_EQ(stats.max_level, 2);
    EXPECT_EQ(stats.cells, scene.asset.levels[2].cells.size());
    const Image8 expected = ExpectedCoverage(scene.asset, 2, v, scene.cameras[v]);
    int covered = 0, mismatched = 0, not_white = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const bool drawn = image.at(x, y, 3) >= 128;
        covered += expected.at(x, y) != 0;
        mismatched += drawn != (expected.at(x, y) != 0);
        if (drawn && image.at(x, y, 0) < 250) ++not_white;
      }
    // Measured (llvmpipe): 0 mismatched of 361 / 370 covered pixels for views 0 / 3; with the
    // expected half flipped (billboards upside down) 711 / 717 mismatch. Bound: 2% of covered.
    EXPECT_GT(covered, 300) << "view " << v;
    EXPECT_LE(mismatched, covered / 50) << "view " << v << ": " << mismatched << " of " << covered;
    EXPECT_EQ(not_white, 0);
  }
}

// The .vtree layout is a matter of the file: an asset written and read again draws the same pixels.
TEST(TreeRenderer, ImageUnchangedThroughTheFileLayout) {
  GlContext context;
  Scene scene = MakeScene(64);
  scene.asset.colour_codebook_size = scene.asset.alpha_codebook_size = 2;
  for (auto& level : scene.asset.levels)
    for (size_t i = 0; i < level.billboards.size(); ++i)
      level.billboards[i].colour = uint16_t(i % 2), level.billboards[i].alpha = uint16_t(i / 3 % 2);
  VtreeWriteOptions zstd;
  zstd.zstd = true;
  const VtreeAsset reloaded = ParseAsset(SerializeAsset(scene.asset, zstd), "tree.vtree");
  TreeRenderer before(scene.asset), after(reloaded);
  for (double azimuth : {0.0, 0.3, 2.0}) {
    const View camera = MakeCamera(Eigen::Vector3d(5 * std::cos(azimuth), 5 * std::sin(azimuth), 2.0), 64);
    const Image8 a = before.Render(camera, {}), b = after.Render(camera, {});
    int drawn = 0;
    for (size_t i = 3; i < a.pixels.size(); i += 4) drawn += a.pixels[i] > 0;
    EXPECT_GT(drawn, 100) << "azimuth " << azimuth;
    EXPECT_TRUE(a.pixels == b.pixels) << "azimuth " << azimuth;
  }
}

// The GPU holds each billboard's tile pair bit-packed (9 + 9 bits for 512 tiles, pairs straddling
// 32-bit words): an atlas of 512 copies of the two tiles, with the billboards naming high tile
// numbers of the same contents, draws what the two-tile asset draws.
TEST(TreeRenderer, PackedTilePairsNameTheTilesTheyMean) {
  GlContext context;
  const Scene scene = MakeScene(64);
  VtreeAsset wide = scene.asset;
  wide.atlas.tiles_per_row = 32;
  wide.atlas.tile_count = 512;
  wide.atlas.width = 32 * 4;
  wide.atlas.height = 16 * 4;
  // Tile t: the opaque tile (0) below 256, the half-opaque one (1) from 256 on (the top bit of 9
  // decides, so a pair read from the wrong bits shows); DXT5 rows of blocks.
  wide.atlas.dxt5.clear();
  for (uint32_t row = 0; row < 16; ++row)
    for (uint32_t column = 0; column < 32; ++column) {
      const auto block = Dxt5Block(row * 32 + column < 256 ? 4 : 2);
      wide.atlas.dxt5.insert(wide.atlas.dxt5.end(), block.begin(), block.end());
    }
  uint32_t n = 0;
  for (auto& level : wide.levels)
    for (auto& b : level.billboards) {
      ++n;
      b.colour = uint16_t((n * 37) % 512);        // white in every tile
      b.alpha = uint16_t(256 + (n * 101) % 256);  // the top half, as tile 1
    }
  TreeRenderer narrow(scene.asset), packed(wide);
  for (int v : {0, 3}) {
    const Image8 a = narrow.Render(scene.cameras[v], {}), b = packed.Render(scene.cameras[v], {});
    int drawn = 0, differ = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      drawn += i % 4 == 3 && a.pixels[i] > 0;
      differ += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 2;
    }
    EXPECT_GT(drawn, 100) << "view " << v;
    EXPECT_EQ(differ, 0) << "view " << v;
  }
}

// render --stats: fragment shader invocations per frame, or -1 where the driver cannot count them.
TEST(TreeRenderer, CountsFragmentsWhereTheDriverCan) {
  GlContext context;
  const Scene scene = MakeScene(64);
  TreeRenderer renderer(scene.asset);
  TreeRenderOptions options;
  FrameStats stats;
  renderer.Render(scene.cameras[0], options, &stats);
  EXPECT_EQ(stats.fragments, -1);  // not asked
  options.count_fragments = true;
  const Image8 image = renderer.Render(scene.cameras[0], options, &stats);
  if (!FragmentCounter::Available()) {
    EXPECT_EQ(stats.fragments, -1);
    GTEST_SKIP() << context.renderer() << " lacks GL_ARB_pipeline_statistics_query";
  }
  int drawn = 0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) drawn += image.pixels[i] > 0;
  // Every drawn pixel ran the fragment shader at least once; quads overlap and cover more than the
  // billboards, so there are more invocations than drawn pixels, but not more than quads x pixels.
  EXPECT_GT(drawn, 100);
  EXPECT_GE(stats.fragments, drawn);
  EXPECT_LE(stats.fragments, int64_t(stats.cells) * 64 * 64);
}

int DrawnPixels(const Image8& image) {
  int drawn = 0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) drawn += image.pixels[i] > 0;
  return drawn;
}

// Quads trimmed to their alpha's extent, and billboards whose alpha is 0 everywhere left out,
// change which fragments run, never a pixel: the scene's billboards are opaque in their top half
// (tile 1) or nowhere (a third tile, 2, for every third billboard).
TEST(TreeRenderer, TrimmedQuadsDrawTheSameImageWithFewerFragments) {
  GlContext context;
  Scene scene = MakeScene(64);
  VtreeAsset& asset = scene.asset;
  asset.atlas.width = 12, asset.atlas.tiles_per_row = 3, asset.atlas.tile_count = 3;
  std::vector<uint8_t> blocks;
  for (int opaque_rows : {4, 2, 0}) {
    const auto block = Dxt5Block(opaque_rows);
    blocks.insert(blocks.end(), block.begin(), block.end());
  }
  asset.atlas.dxt5 = blocks;  // one row of three blocks
  int n = 0;
  for (auto& level : asset.levels)
    for (auto& b : level.billboards) b.alpha = uint16_t(++n % 3 == 0 ? 2 : 1);
  TreeRenderer renderer(asset);
  TreeRenderOptions trimmed, full;
  trimmed.count_fragments = full.count_fragments = true;
  full.trim_quads = false;
  const std::vector<View> cameras = {scene.cameras[0], scene.cameras[3],
                                     MakeCamera(Eigen::Vector3d(5 * std::cos(0.3), 5 * std::sin(0.3), 2.0), 64),
                                     MakeCamera(Eigen::Vector3d(-1.0, 2.5, 5.0), 64),   // from above
                                     MakeCamera(Eigen::Vector3d(2.2, -2.0, 1.2), 64)};  // close
  int64_t trimmed_fragments = 0, full_fragments = 0;
  for (size_t c = 0; c < cameras.size(); ++c) {
    FrameStats a, b;
    const Image8 with = renderer.Render(cameras[c], trimmed, &a), without = renderer.Render(cameras[c], full, &b);
    EXPECT_GT(DrawnPixels(with), 100) << "camera " << c;
    EXPECT_TRUE(with.pixels == without.pixels) << "camera " << c;
    EXPECT_LT(a.billboards, b.billboards) << "camera " << c;
    if (FragmentCounter::Available()) {
      EXPECT_LT(a.fragments, b.fragments) << "camera " << c;
      trimmed_fragments += a.fragments, full_fragments += b.fragments;
    }
  }
  // Measured (llvmpipe): 36-89 % per camera (least from above, where the two views' opaque halves
  // lie apart), 63 % in all; the opaque top half is half of each square.
  if (FragmentCounter::Available()) {
    EXPECT_LT(trimmed_fragments, 0.75 * full_fragments) << trimmed_fragments << " of " << full_fragments;
  }
}

// One opaque billboard seen from its own input view: the trimmed quad is the square's image, so
// the fragments shaded are the pixels it covers, give or take its edge.
TEST(TreeRenderer, FragmentsOfOneOpaqueSquareAreItsPixels) {
  GlContext context;
  constexpr int kSize = 96;
  Scene scene = MakeScene(kSize);
  VtreeAsset& asset = scene.asset;
  asset.levels.resize(1);
  asset.levels[0].billboards.clear();
  for (uint16_t v = 0; v < 8; ++v) asset.levels[0].billboards.push_back({0, v, 0, 0});  // tile 0: opaque
  TreeRenderer renderer(asset);
  TreeRenderOptions options;
  options.count_fragments = true;
  FrameStats stats;
  const Image8 image = renderer.Render(scene.cameras[0], options, &stats);
  if (!FragmentCounter::Available()) GTEST_SKIP() << context.renderer() << " lacks GL_ARB_pipeline_statistics_query";
  const int drawn = DrawnPixels(image);
  EXPECT_EQ(stats.billboards, 1u);
  EXPECT_GT(drawn, 1000);
  EXPECT_GE(stats.fragments, drawn);
  // llvmpipe counts whole 4 x 4 blocks (other drivers pixels or 2 x 2 quads): at most the blocks
  // that the square's side touches, one more each way.
  const int blocks = int(std::sqrt(double(drawn)) / 4) + 2;
  EXPECT_LE(stats.fragments, 16 * blocks * blocks) << stats.fragments << " for " << drawn;
  const int64_t trimmed = stats.fragments;
  options.trim_quads = false;  // 5 % wider each way
  renderer.Render(scene.cameras[0], options, &stats);
  EXPECT_GE(stats.fragments, trimmed);
}

TEST(TreeRenderer, TransparentWhereNothingIsAndBackgroundIsComposited) {
  GlContext context;
  const Scene scene = MakeScene(48);
  TreeRenderer renderer(scene.asset);
  View away = scene.cameras[0];
  away.pose = Pose::LookAt(Eigen::Vector3d(5, 0, 2.5), Eigen::Vector3d(10, 0, 2.5), Eigen::Vector3d::UnitZ());
  TreeRenderOptions options;
  FrameStats stats;
  const Image8 empty = renderer.Render(away, options, &stats);
  for (size_t i = 3; i < empty.pixels.size(); i += 4) ASSERT_EQ(empty.pixels[i], 0);
  options.background = {0, 0, 1, 1};
  const Image8 blue = renderer.Render(scene.cameras[1], options, &stats);
  EXPECT_EQ(blue.at(0, 0, 2), 255);
  EXPECT_EQ(blue.at(0, 0, 3), 255);
  EXPECT_GT(stats.billboards, 0u);
}

TEST(TreeRenderer, BetweenTwoViewsBlendsBoth) {
  GlContext context;
  const Scene scene = MakeScene(48);
  TreeRenderer renderer(scene.asset);
  // Half-way between views 0 and 1 in azimuth: both weigh about one half.
  const double azimuth = std::numbers::pi / 8;
  const View camera = MakeCamera(Eigen::Vector3d(5 * std::cos(azimuth), 5 * std::sin(azimuth), 2.5), 48);
  std::vector<FrameRecord> records;
  const FrameStats stats = renderer.Plan(camera, {}, &records);
  EXPECT_NEAR(stats.views.first_weight, 0.5, 0.01);
  EXPECT_TRUE((stats.views.first == 0 && stats.views.second == 1) ||
              (stats.views.first == 1 && stats.views.second == 0));
  EXPECT_EQ(stats.billboards, 2 * stats.cells);
}

// The GPU holds the atlas, the alpha extents and one frame's records, no table of cells or
// billboards: each record names its cell by coordinates and level and carries its tiles, and the
// record buffer never outgrows one record per leaf cell, however the frames are drawn.
TEST(TreeRenderer, RecordsCarryTheCellAndItsTilesAndTheBuffersStayWithinTheLeaves) {
  GlContext context;
  const Scene scene = MakeScene(48);
  TreeRenderer renderer(scene.asset);
  const double between_views = 2 * std::numbers::pi * 3.5 / 8;  // both blended views are drawn
  const View camera = MakeCamera(Eigen::Vector3d(5 * std::cos(between_views), 5 * std::sin(between_views), 2.5), 48);
  for (int level : {0, 1, 2}) {
    TreeRenderOptions options;
    options.lod.forced_level = level;
    std::vector<FrameRecord> records;
    renderer.Plan(camera, options, &records);
    ASSERT_EQ(records.size(), scene.asset.levels[level].cells.size()) << "level " << level;
    for (const FrameRecord& record : records) {
      EXPECT_EQ(record[3] & 0xffu, uint32_t(level));
      EXPECT_EQ(record[3] >> 8, 3u) << "both views have a billboard in every cell";
      EXPECT_EQ(record[1], 0u | 1u << 16) << "colour tile 0, alpha tile 1";
      const std::array<uint16_t, 3> cell = {uint16_t(record[0] & 0x3ff), uint16_t(record[0] >> 10 & 0x3ff),
                                            uint16_t(record[0] >> 20)};
      const auto& cells = scene.asset.levels[level].cells;
      EXPECT_NE(std::find(cells.begin(), cells.end(), cell), cells.end()) << "level " << level;
    }
  }
  for (double distance : {5.0, 1.5, 40.0})
    for (int level : {-1, 2, 1, 2}) {
      TreeRenderOptions options;
      options.lod.forced_level = level;
      renderer.Render(MakeCamera(Eigen::Vector3d(distance, 0.3 * distance, 1.5), 48), options);
    }
  const size_t records = scene.asset.LeafCellCount() * sizeof(FrameRecord), extents = 16;  // 2 tiles, bound >= 16 B
  EXPECT_EQ(scene.asset.LeafCellCount(), 6u);
  EXPECT_GT(renderer.GpuBytes().buffers, extents);
  EXPECT_LE(renderer.GpuBytes().buffers, extents + records);
  EXPECT_EQ(renderer.GpuBytes().atlas, scene.asset.atlas.dxt5.size());
}

TEST(TreeRenderer, UnpremultiplyRounds) {
  Image8 image(2, 1, 4);
  image.pixels = {64, 32, 0, 128, 10, 10, 10, 0};
  const Image8 straight = Unpremultiply(image);
  EXPECT_EQ(straight.at(0, 0, 0), 128);
  EXPECT_EQ(straight.at(0, 0, 1), 64);
  EXPECT_EQ(straight.at(0, 0, 3), 128);
  EXPECT_EQ(straight.at(1, 0, 0), 0);
}

}  // namespace
}  // namespace voltree
