// The mattes checked against each other through the cameras, on exact silhouettes: a ring of 12
// cameras around tall boxes, each matte the boxes' true silhouette. One box is one tree; two
// boxes apart are two objects in the ring, which one asset cannot hold apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "capture/matte/consistency.h"
#include "core/error.h"
#include "expect_check_names.h"

namespace voltree {
namespace {

struct Box {
  Eigen::Vector3d lo, hi;
  uint8_t alpha = 255;  // of the pixels that see it
};

// Whether the ray from `origin` along `direction` meets the box (slab test).
bool Hits(const Box& box, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  double near = 0, far = 1e9;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-12) {
      if (origin[axis] < box.lo[axis] || origin[axis] > box.hi[axis]) return false;
      continue;
    }
    double t0 = (box.lo[axis] - origin[axis]) / direction[axis], t1 = (box.hi[axis] - origin[axis]) / direction[axis];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

struct RingSet {
  std::vector<View> views;
  std::vector<Image8> mattes;
};

// 12 cameras on a ring of radius 5 at 1.5 above the ground, 64² pixels, looking at (0, 0, 1).
RingSet PhotographRing(const std::vector<Box>& boxes) {
  RingSet set;
  for (int i = 0; i < 12; ++i) {
    const double angle = 2 * M_PI * i / 12;
    View view;
    view.name = Str("view_", i, ".png");
    view.camera = Camera::Pinhole(64, 64, 48, 48, 32, 32);
    view.pose = Pose::LookAt({5 * std::cos(angle), 5 * std::sin(angle), 1.5}, {0, 0, 1}, {0, 0, 1});
    Image8 matte(64, 64, 1);
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const Eigen::Vector3d ray = view.PixelRay({x + 0.5, y + 0.5});
        for (const Box& box : boxes)
          if (Hits(box, view.pose.Center(), ray))
            matte.pixels[size_t(y) * 64 + x] = std::max(matte.pixels[size_t(y) * 64 + x], box.alpha);
      }
    set.views.push_back(view);
    set.mattes.push_back(std::move(matte));
  }
  return set;
}

TEST(MatteConsistency, OneTreeIsOnePart) {
  const RingSet set = PhotographRing({{{-0.2, -0.2, 0}, {0.2, 0.2, 2}}});
  const MatteConsistency consistency = MeasureMatteConsistency(set.views, set.mattes, MatteConsistencyOptions{});
  ASSERT_FALSE(consistency.parts.empty());
  const size_t second = consistency.parts.size() > 1 ? consistency.parts[1].voxels : 0;
  std::printf("one box: %zu parts, the largest %zu voxels, the second %zu\n", consistency.parts.size(),
              consistency.parts[0].voxels, second);
  EXPECT_LT(double(second), 0.05 * double(consistency.parts[0].voxels));
  EXPECT_NO_THROW(CheckMatteConsistency(consistency, MatteConsistencyOptions{}, "mattes"));
}

TEST(MatteConsistency, TwoTreesInTheRingAreNamed) {
  const RingSet set = PhotographRing({{{-1.6, -0.2, 0}, {-1.2, 0.2, 2}}, {{1.2, -0.2, 0}, {1.6, 0.2, 1.6}}});
  const MatteConsistency consistency = MeasureMatteConsistency(set.views, set.mattes, MatteConsistencyOptions{});
  ASSERT_GE(consistency.parts.size(), 2u);
  std::printf("two boxes: parts of %zu and %zu voxels, around x = %.2f and %.2f\n", consistency.parts[0].voxels,
              consistency.parts[1].voxels, consistency.parts[0].center.x(), consistency.parts[1].center.x());
  EXPECT_NEAR(std::abs(consistency.parts[0].center.x()), 1.4, 0.15);
  EXPECT_NEAR(std::abs(consistency.parts[1].center.x()), 1.4, 0.15);
  try {
    CheckMatteConsistency(consistency, MatteConsistencyOptions{}, "ws/mattes");
    FAIL() << "two boxes passed the check";
  } catch (const Error& error) {
    const std::string message = error.what();
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find("ws/mattes"), std::string::npos) << message;
    EXPECT_NE(message.find("two separate objects"), std::string::npos) << message;
    EXPECT_NE(message.find("one tree at a time"), std::string::npos) << message;
  }
}

// A branch every photo but one holds in part (alpha 0.2, the share of each pixel its leaves cover,
// once the mixed pixels are solved) and that one photo holds whole. Carved wherever a photo's
// alpha is under the tree's threshold, the branch left the hull and that photo's recall fell
// under the guard's limit; it is carved only where a photo is sure of the background.
TEST(MatteConsistency, ABranchHeldInPartStaysInTheHull) {
  const Box trunk{{-0.2, -0.2, 0}, {0.2, 0.2, 2}};
  Box branch{{-0.05, -1.8, 1.1}, {0.05, 0, 1.4}, 51};
  RingSet set = PhotographRing({trunk, branch});
  branch.alpha = 255;
  const size_t whole = 0;  // the camera at (5, 0, 1.5) sees the branch broadside
  set.mattes[whole] = PhotographRing({trunk, branch}).mattes[whole];
  const auto recall_of_the_whole_photo = [&](double carve_threshold) {
    MatteConsistencyOptions options;
    options.carve_threshold = carve_threshold;
    return MeasureMatteConsistency(set.views, set.mattes, options).photos[whole].recall;
  };
  const double strict = recall_of_the_whole_photo(MatteConsistencyOptions{}.matte_threshold);
  const double lenient = recall_of_the_whole_photo(MatteConsistencyOptions{}.carve_threshold);
  std::printf("recall of the photo that holds the branch whole: %.3f carved at the tree's threshold, %.3f now\n",
              strict, lenient);
  EXPECT_LT(strict, MatteConsistencyOptions{}.min_recall);
  EXPECT_GT(lenient, 0.97);
}

TEST(MatteConsistencyOptions, CheckNamesTheCarveThreshold) {
  MatteConsistencyOptions options;
  options.carve_threshold = 0.5;
  testing::ExpectCheckNames(options, "carve threshold");
}

}  // namespace
}  // namespace voltree
