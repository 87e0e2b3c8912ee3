// The numbers that make an oak an oak: a Weber–Penn style description of a tree (trunk, then one
// BranchLevel per generation of branches) plus its foliage. Presets fill these in.
#pragma once

#include <cstdint>
#include <vector>

#include "samples/procedural_tree.h"

namespace voltree {

// How the length of the trunk's children varies from the crown base (0) to the top (1).
enum class CrownShape {
  kDome,  // longest in the lower middle: broad rounded crowns (oak)
  kCone,  // longest at the bottom: conifers
};

enum class FoliageKind { kBroadLeaves, kNeedles };

// One generation of branches. Children are spawned by a branch of the previous level.
struct BranchLevel {
  int segments = 6;         // polyline segments of one branch
  int sides = 6;            // tube resolution around the branch
  float tip_radius = 0.3f;  // tip radius / base radius
  float bend_deg = 6.0f;    // random turn per segment
  float up_pull = 0.0f;     // per segment pull toward +Z (negative: droop)
  // How this level is spawned on its parent:
  float per_metre = 4.0f;       // children per metre of the parent's spawning span
  float start = 0.2f;           // fraction of the parent's length before the first child
  float length_ratio = 0.5f;    // child length / parent length (before shape factors)
  float angle_deg = 45.0f;      // angle to the parent's direction
  float angle_top_deg = 45.0f;  // same at the parent's tip (interpolated along the parent)
  float angle_jitter_deg = 10.0f;
  int whorl = 1;  // children per spawning point (conifer whorls > 1)
};

struct FoliageShape {
  FoliageKind kind = FoliageKind::kBroadLeaves;
  int count = 20000;          // leaf quads, placed exactly
  float size = 0.3f;          // quad edge in metres (a quad holds a small cluster of leaves)
  float size_jitter = 0.25f;  // relative
  int first_level = 2;        // levels >= this carry leaves
  float start = 0.3f;         // fraction of a branch's length that stays bare
  float spread = 0.6f;        // randomness of the leaf direction (0: along the twig)
  // Leaf density deep inside the crown relative to its outer shell, where the light is.
  float inner_density = 0.2f;
};

// An ellipsoid around the trunk axis that branch tips are kept inside (Weber–Penn "pruning"),
// which rounds the crown. Disabled while radius_xy is 0.
struct CrownEnvelope {
  float center_z = 0.0f;
  float radius_xy = 0.0f;
  float radius_z = 0.0f;
  float bumpiness = 0.12f;  // random relative reach per branch: a lumpy, not a perfect, dome
};

struct TreeShape {
  float height = 10.0f;        // trunk length in metres (the crown may add a little)
  float trunk_radius = 0.25f;  // at the base, above the flare
  float flare = 0.6f;          // extra relative radius at the ground
  float lean_deg = 3.0f;       // random lean of the trunk
  float radius_power = 1.2f;   // child radius = parent radius * (child/parent length)^power
  float min_radius = 0.004f;
  CrownShape crown = CrownShape::kDome;
  CrownEnvelope envelope;
  std::vector<BranchLevel> levels;  // levels[0] is the trunk
  FoliageShape foliage;
};

TreeShape PresetShape(TreePreset preset);

}  // namespace voltree
