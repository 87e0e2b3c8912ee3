#include "samples/tree_shape.h"

#include "core/error.h"

namespace voltree {
namespace {

BranchLevel Level(int segments, int sides, float tip_radius, float bend_deg, float up_pull) {
  BranchLevel level;
  level.segments = segments;
  level.sides = sides;
  level.tip_radius = tip_radius;
  level.bend_deg = bend_deg;
  level.up_pull = up_pull;
  return level;
}

BranchLevel Spawned(BranchLevel level, float per_metre, float start, float length_ratio, float angle_deg,
                    float angle_top_deg, float angle_jitter_deg, int whorl = 1) {
  level.per_metre = per_metre;
  level.start = start;
  level.length_ratio = length_ratio;
  level.angle_deg = angle_deg;
  level.angle_top_deg = angle_top_deg;
  level.angle_jitter_deg = angle_jitter_deg;
  level.whorl = whorl;
  return level;
}

// ~10 m tall, ~10 m broad: a short clear trunk, spreading limbs that turn up, a dense dome.
TreeShape OakShape() {
  TreeShape shape;
  shape.height = 6.4f;
  shape.trunk_radius = 0.28f;
  shape.flare = 0.55f;
  shape.lean_deg = 4.0f;
  shape.crown = CrownShape::kDome;
  shape.envelope = {5.4f, 5.2f, 5.0f, 0.12f};
  shape.levels = {
      Level(8, 16, 0.12f, 4.0f, 0.0f),
      Spawned(Level(7, 10, 0.25f, 9.0f, 0.05f), 2.2f, 0.33f, 1.0f, 80.0f, 30.0f, 10.0f),
      Spawned(Level(4, 6, 0.3f, 14.0f, 0.03f), 2.6f, 0.12f, 0.5f, 50.0f, 40.0f, 15.0f),
      Spawned(Level(2, 4, 0.4f, 15.0f, 0.0f), 6.0f, 0.1f, 0.42f, 45.0f, 40.0f, 15.0f),
  };
  shape.foliage = {FoliageKind::kBroadLeaves, 24000, 0.34f, 0.25f, 2, 0.3f, 0.6f, 0.15f};
  return shape;
}

// ~12 m tall cone: a straight leader with whorls of near-horizontal branches, needle shoots.
TreeShape PineShape() {
  TreeShape shape;
  shape.height = 11.6f;
  shape.trunk_radius = 0.2f;
  shape.flare = 0.3f;
  shape.lean_deg = 2.0f;
  shape.crown = CrownShape::kCone;
  shape.levels = {
      Level(10, 12, 0.05f, 2.0f, 0.02f),
      Spawned(Level(5, 6, 0.2f, 6.0f, 0.03f), 9.0f, 0.2f, 0.27f, 98.0f, 55.0f, 8.0f, 5),
      Spawned(Level(3, 4, 0.3f, 10.0f, 0.0f), 5.0f, 0.1f, 0.35f, 60.0f, 50.0f, 10.0f, 2),
  };
  shape.foliage = {FoliageKind::kNeedles, 14000, 0.36f, 0.2f, 1, 0.25f, 0.3f, 0.3f};
  return shape;
}

// ~5 m sapling: few limbs, few leaves, see-through crown.
TreeShape YoungOakShape() {
  TreeShape shape;
  shape.height = 4.3f;
  shape.trunk_radius = 0.07f;
  shape.flare = 0.3f;
  shape.lean_deg = 5.0f;
  shape.crown = CrownShape::kDome;
  shape.levels = {
      Level(6, 10, 0.15f, 5.0f, 0.0f),
      Spawned(Level(5, 6, 0.25f, 12.0f, 0.06f), 3.0f, 0.3f, 0.45f, 60.0f, 30.0f, 12.0f),
      Spawned(Level(3, 4, 0.35f, 15.0f, 0.02f), 5.0f, 0.15f, 0.42f, 50.0f, 40.0f, 15.0f),
      Spawned(Level(2, 3, 0.5f, 15.0f, 0.0f), 8.0f, 0.15f, 0.4f, 45.0f, 40.0f, 15.0f),
  };
  shape.foliage = {FoliageKind::kBroadLeaves, 1400, 0.22f, 0.25f, 2, 0.4f, 0.6f, 0.5f};
  return shape;
}

}  // namespace

TreeShape PresetShape(TreePreset preset) {
  switch (preset) {
    case TreePreset::kOak:
      return OakShape();
    case TreePreset::kPine:
      return PineShape();
    case TreePreset::kYoungOak:
      return YoungOakShape();
  }
  Fail("unknown tree preset ", static_cast<int>(preset));
}

}  // namespace voltree
