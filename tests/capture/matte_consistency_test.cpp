// The mattes checked against each other through the cameras, on exact silhouettes: a ring of 12
// cameras around tall boxes, each matte the boxes' true silhouette. One box is one tree; two
// boxes apart are two objects in the ring, which one asset cannot hold apart.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "capture/matte/consistency.h"
#include "core/error.h"

namespace voltree {
namespace {

struct Box {
  Eigen::Vector3d lo, hi;
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
          if (Hits(box, view.pose.Center(), ray)) matte.pixels[size_t(y) * 64 + x] = 255;
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

}  // namespace
}  // namespace voltree
