// The refinement after mapping, through the real `colmap point_filtering` and `bundle_adjuster`,
// on a small model made here: cameras on a ring around a cloud of points, observations with
// sub-pixel noise, and some observations a few pixels off (what the mapper keeps below its 4 px).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "capture/calibrate_accuracy.h"
#include "capture/colmap_refine.h"
#include "capture/colmap_runner.h"
#include "core/colmap_model.h"
#include "core/error.h"
#include "temp_dir.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

// `views` cameras at 5 units from the origin, looking at it; 400 points in the unit cube. Each
// point is observed by every camera that sees it, with Gaussian noise of 0.25 px; one observation
// in `outlier_every` is moved 2.5-3.5 px instead.
ColmapModel RingModel(int views, int outlier_every, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), angle(0, 2 * M_PI), offset(2.5, 3.5);
  std::normal_distribution<double> noise(0, 0.25);
  ColmapModel model;
  model.cameras[1] = Camera::Pinhole(320, 240, 300, 300, 160, 120);
  for (int v = 0; v < views; ++v) {
    const double azimuth = 2 * M_PI * v / views, elevation = (v % 2 ? 10 : 30) * M_PI / 180;
    const Eigen::Vector3d eye = 5 * Eigen::Vector3d(std::cos(azimuth) * std::cos(elevation),
                                                    std::sin(azimuth) * std::cos(elevation), std::sin(elevation));
    ColmapImage image;
    image.image_id = v + 1;
    image.camera_id = 1;
    image.name = "view_" + std::to_string(100 + v) + ".png";
    image.pose = Pose::LookAt(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
    model.images[image.image_id] = image;
  }
  int observation = 0;
  for (int64_t p = 1; p <= 400; ++p) {
    ColmapPoint point;
    point.point_id = p;
    point.position = {unit(rng), unit(rng), unit(rng)};
    for (auto& [id, image] : model.images) {
      const View view{image.name, model.cameras.at(1), image.pose};
      Eigen::Vector2d pixel;
      if (!view.WorldToPixel(point.position, &pixel)) continue;
      if (++observation % outlier_every == 0) {
        const double a = angle(rng);
        pixel += offset(rng) * Eigen::Vector2d(std::cos(a), std::sin(a));
      } else {
        pixel += Eigen::Vector2d(noise(rng), noise(rng));
      }
      point.track.push_back({id, int(image.keypoints.size())});
      image.keypoints.push_back(pixel);
      image.point3d_ids.push_back(p);
    }
    model.points[p] = point;
  }
  return model;
}

struct Outcome {
  RefinedModel refined;
  CameraAccuracy accuracy;
};

Outcome Refine(const fs::path& dir, const ColmapModel& model, const ColmapModel& truth,
               const ModelRefinementOptions& options) {
  fs::remove_all(dir);
  WriteColmapText(dir / "mapped", model);
  Progress quiet(true);
  Outcome out;
  out.refined = RefineColmapModel(FindColmap(), dir / "mapped", model, dir / "refined", options, quiet);
  out.accuracy = CompareCameras(out.refined.model.Views(), truth.Views());
  return out;
}

TEST(ColmapRefine, DroppingFarObservationsBringsTheCamerasCloser) {
  const ColmapModel observed = RingModel(12, 8, 7);
  const ColmapModel truth = RingModel(12, 8, 7);  // the same cameras; its observations are not used
  const testing::TempDir temp("colmap_refine");
  const fs::path& dir = temp.path;

  // The baseline: bundle adjustment of every observation, as the mapper leaves the model.
  ModelRefinementOptions keep_all;
  keep_all.rounds = 1;
  keep_all.max_error = 1e6;
  const Outcome adjusted = Refine(dir / "all", observed, truth, keep_all);
  const Outcome refined = Refine(dir / "filtered", observed, truth, ModelRefinementOptions{});
  std::printf(
      "bundle adjustment only: max rotation %.4f deg, centre %.4f %%; refined (%d rounds, %zu of %zu observations): "
      "%.4f deg, %.4f %%\n",
      adjusted.accuracy.max_rotation_degrees, 100 * adjusted.accuracy.max_center_error, refined.refined.rounds_taken,
      ObservationCount(refined.refined.model), ObservationCount(observed), refined.accuracy.max_rotation_degrees,
      100 * refined.accuracy.max_center_error);
  ASSERT_EQ(refined.refined.rounds_taken, 2);
  EXPECT_EQ(refined.accuracy.matched, 12);
  EXPECT_EQ(ObservationCount(adjusted.refined.model), ObservationCount(observed));  // the baseline kept everything
  // One in 8 observations is off: all 600 of them go, and almost none of the 4200 good ones.
  EXPECT_LE(ObservationCount(refined.refined.model), ObservationCount(observed) * 7 / 8);
  EXPECT_GE(ObservationCount(refined.refined.model), ObservationCount(observed) * 7 / 8 - 50);
  EXPECT_LT(MeanReprojectionError(refined.refined.model), 0.5 * MeanReprojectionError(observed));
  // Measured: 0.304 deg and 0.51 % with every observation, 0.064 deg and 0.11 % refined.
  EXPECT_LT(refined.accuracy.max_rotation_degrees, 0.1);
  EXPECT_LT(refined.accuracy.max_rotation_degrees, 0.5 * adjusted.accuracy.max_rotation_degrees);
  EXPECT_LT(refined.accuracy.max_center_error, 0.5 * adjusted.accuracy.max_center_error);
}

TEST(ColmapRefine, KnownIntrinsicsStayAsGiven) {
  ColmapModel observed = RingModel(8, 8, 11);
  observed.cameras[1] = Camera::Pinhole(320, 240, 310, 310, 160, 120);  // 3 % off: adjustment would move it
  const testing::TempDir temp("colmap_refine_intrinsics");
  const fs::path& dir = temp.path;
  ModelRefinementOptions options;
  options.keep_intrinsics = true;
  const Outcome kept = Refine(dir / "kept", observed, observed, options);
  EXPECT_DOUBLE_EQ(kept.refined.model.cameras.at(1).FocalX(), 310);
  options.keep_intrinsics = false;
  const Outcome moved = Refine(dir / "moved", observed, observed, options);
  EXPECT_GT(std::abs(moved.refined.model.cameras.at(1).FocalX() - 310), 1.0);
}

TEST(ColmapRefine, OptionsAreChecked) {
  ModelRefinementOptions options;
  options.max_error = 0.5;
  EXPECT_THROW(options.Check(), Error);
  options = {};
  options.rounds = -1;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace voltree
