// The billboard fit: on a scene where the tomography's billboards lose a thin opaque pole behind
// a sparse crown, the fitted billboards reproduce the input views much better, the pole survives
// in held-out views, the loss never rises, and the result does not depend on the thread count.
#include <gtest/gtest.h>

#include "needs_two_cores.h"
#include "reconstruct/billboard_raster.h"
#include "synthetic_scene.h"

namespace voltree {
namespace {

constexpr int kSize = 96;

// A sparse crown of opaque "leaves" (single voxels of a 32^3 grid, one in eight inside a ball,
// from a fixed hash) and an opaque pole one voxel (half a finest cell) wide from the ground up to
// the crown's centre: hard edges and thin parts, what the tomography's soft billboards lose.
constexpr double kOpaque = 60.0;

void AddPole(testing::Phantom* p) {
  for (int z = 0; z < 18; ++z) p->at(16, 16, z) = kOpaque;
}

testing::Phantom PoleAndCrown() {
  testing::Phantom p{32, std::vector<double>(32 * 32 * 32, 0.0)};
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const Eigen::Vector3d c((x + 0.5) / 32, (y + 0.5) / 32, (z + 0.5) / 32);
        const uint32_t hash = (uint32_t(x) * 73856093u) ^ (uint32_t(y) * 19349663u) ^ (uint32_t(z) * 83492791u);
        if ((c - Eigen::Vector3d(0.5, 0.5, 0.62)).norm() < 0.3 && hash % 8 == 0) p.at(x, y, z) = kOpaque;
      }
  AddPole(&p);
  return p;
}

testing::Phantom PoleOnly() {
  testing::Phantom p{32, std::vector<double>(32 * 32 * 32, 0.0)};
  AddPole(&p);
  return p;
}

// The two input views nearest in angle to `camera`, weighted as the renderer weighs them.
ViewBlend NearestTwo(const Volume& volume, const View& camera) {
  const Eigen::Vector3d centre = volume.origin + Eigen::Vector3d::Constant(0.5 * volume.size);
  const Eigen::Vector3d look = centre - camera.pose.Center();
  std::vector<std::pair<double, int>> angles;
  for (int v = 0; v < int(volume.views.size()); ++v) {
    const Eigen::Vector3d other = centre - volume.views[v].position;
    angles.push_back({std::atan2(look.cross(other).norm(), look.dot(other)), v});
  }
  std::sort(angles.begin(), angles.end());
  const double a1 = angles[0].first, a2 = angles[1].first;
  return ViewBlend{angles[0].second, angles[1].second, float(a2 / (a1 + a2)), float(a1 / (a1 + a2))};
}

double AlphaPsnr(const ImageF& render, const Image8& matte) {
  double squared = 0;
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x) {
      const double e = render.at(x, y, 3) - matte.at(x, y) / 255.0;
      squared += e * e;
    }
  return 10 * std::log10(double(matte.width) * matte.height / std::max(squared, 1e-12));
}

// Share of the pixels where the pole shows (alone it would be opaque, and the truth is) that the
// render covers (alpha > 0.5).
double PoleRecall(const ImageF& render, const Image8& matte, const Image8& pole) {
  int pole_pixels = 0, covered = 0;
  for (int y = 0; y < matte.height; ++y)
    for (int x = 0; x < matte.width; ++x)
      if (pole.at(x, y) > 200 && matte.at(x, y) > 200) {
        ++pole_pixels;
        covered += render.at(x, y, 3) > 0.5f;
      }
  return pole_pixels ? double(covered) / pole_pixels : 1.0;
}

struct Fixture {
  testing::Phantom scene = PoleAndCrown();
  ReconstructInput input = testing::PhantomInput(scene, 16, kSize);
  std::vector<View> held_out;
  std::vector<Image8> held_out_mattes, held_out_poles;

  Fixture() {
    // Held-out cameras half-way between the input ones, at an elevation no input view has.
    for (const View& view : testing::RingViews(32, kSize)) {
      const int index = std::stoi(view.name.substr(5, 3));
      if (index % 8 != 1) continue;
      View v = view;
      const Eigen::Vector3d centre(0.5, 0.5, 0.5);
      const Eigen::Vector3d eye =
          centre + Eigen::AngleAxisd(0.15, Eigen::Vector3d::UnitY()) * (v.pose.Center() - centre);
      v.pose = Pose::LookAt(eye, centre, Eigen::Vector3d::UnitZ());
      held_out.push_back(v);
      held_out_mattes.push_back(testing::PhantomMatte(scene, v));
      held_out_poles.push_back(testing::PhantomMatte(PoleOnly(), v));
    }
  }

  Volume Make(bool fit, int threads, ReconstructStats* stats = nullptr) const {
    ReconstructOptions options;
    options.levels = 5;
    options.threads = threads;
    options.fit.enabled = fit;
    Progress quiet(true);
    return Reconstruct(input, options, &quiet, stats);
  }
};

const Fixture& Shared() {
  static const Fixture fixture;
  return fixture;
}

TEST(BillboardFit, ReproducesTheInputViewsAndKeepsThePole) {
  const Fixture& f = Shared();
  const Volume before = f.Make(false, 2);
  ReconstructStats stats;
  const Volume after = f.Make(true, 2, &stats);
  const int finest = int(after.levels.size()) - 1;

  double input_before = 0, input_after = 0;
  for (size_t v = 0; v < f.input.views.size(); ++v) {
    const ViewBlend self{int(v), -1, 1, 0};
    const ImageF a = CompositeLayers(RasterizeLevel(before, finest, f.input.views[v], self, 1.0),
                                     TexelsAsFloat(before.levels[finest]));
    const ImageF b = CompositeLayers(RasterizeLevel(after, finest, f.input.views[v], self, 1.0),
                                     TexelsAsFloat(after.levels[finest]));
    input_before += AlphaPsnr(a, f.input.mattes[v]) / f.input.views.size();
    input_after += AlphaPsnr(b, f.input.mattes[v]) / f.input.views.size();
  }
  double held_before = 0, held_after = 0, pole_before = 0, pole_after = 0;
  for (size_t h = 0; h < f.held_out.size(); ++h) {
    const ImageF a =
        CompositeLayers(RasterizeLevel(before, finest, f.held_out[h], NearestTwo(before, f.held_out[h]), 1.0),
                        TexelsAsFloat(before.levels[finest]));
    const ImageF b =
        CompositeLayers(RasterizeLevel(after, finest, f.held_out[h], NearestTwo(after, f.held_out[h]), 1.0),
                        TexelsAsFloat(after.levels[finest]));
    held_before += AlphaPsnr(a, f.held_out_mattes[h]) / f.held_out.size();
    held_after += AlphaPsnr(b, f.held_out_mattes[h]) / f.held_out.size();
    pole_before += PoleRecall(a, f.held_out_mattes[h], f.held_out_poles[h]) / f.held_out.size();
    pole_after += PoleRecall(b, f.held_out_mattes[h], f.held_out_poles[h]) / f.held_out.size();
  }
  std::printf(
      "finest level alpha PSNR, input views: %.2f -> %.2f dB; held-out: %.2f -> %.2f dB; "
      "held-out pole recall %.3f -> %.3f\n",
      input_before, input_after, held_before, held_after, pole_before, pole_after);
  for (const BillboardFitLevel& l : stats.fit.levels)
    std::printf("  level %d (1/%.1f): alpha %.2f -> %.2f dB, RGB %.2f -> %.2f dB\n", l.level, l.scale,
                l.alpha_psnr_before, l.alpha_psnr_after, l.rgb_psnr_before, l.rgb_psnr_after);
  EXPECT_GT(input_after, input_before + 6.0);  // measured +9.1 dB (33.73 -> 42.80)
  EXPECT_GT(held_after, held_before);          // measured +0.16 dB (25.53 -> 25.69)
  // The pole holds: measured 1.000 -> 0.988 (the fit sharpens its edge pixels against the
  // input views; with --prune 0.95 the tomography's billboards scored 0.988 as well).
  EXPECT_GE(pole_after, pole_before - 0.02);
  EXPECT_GT(pole_after, 0.95);
}

TEST(BillboardFit, NeverRaisesTheLoss) {
  ReconstructStats stats;
  Shared().Make(true, 2, &stats);
  ASSERT_EQ(stats.fit.levels.size(), 5u);
  for (const BillboardFitLevel& l : stats.fit.levels) {
    EXPECT_LE(l.loss_after, l.loss_before) << "level " << l.level;
    EXPECT_GE(l.alpha_psnr_after, l.alpha_psnr_before - 0.05) << "level " << l.level;
  }
  EXPECT_TRUE(stats.fit.warnings.empty());
}

TEST(BillboardFit, DoesNotDependOnTheThreadCount) {
  VOLTREE_SKIP_UNLESS_TWO_CORES();
  const Volume one = Shared().Make(true, 1), two = Shared().Make(true, 2);
  for (size_t l = 0; l < one.levels.size(); ++l) EXPECT_EQ(one.levels[l].texels, two.levels[l].texels) << "level " << l;
}

}  // namespace
}  // namespace voltree
