// Scenes of tree meshes drawn with a level-of-detail method per instance (`voltree render SCENE
// --lod METHOD`), the methods of `voltree lod-bench` under the same names:
// - mesh: the full mesh at every distance (the reference);
// - points: Deussen et al. 2002, a prefix of points and lines sized by the tree's screen size,
//   the full mesh where it needs more points than were sampled (their switch, sec. 5.1);
// - ellipsoids: Clasen et al., the level of leaf-cluster ellipsoids and simplified branch lines
//   the screen size picks;
// - cook: stochastic pruning, the first lambda = (size / full_pixels)^2 of a random leaf order,
//   each survivor's area scaled by 1 / lambda;
// - neubert: Neubert et al. 2011, cook's lambda of the leaves in their rendering-priority order
//   (sec. 3), lowered for trees that others hide, lambda * max(f, 0.1) with f the visible part
//   of the crown in the previous frame's depth (sec. 4, lod/occlusion_factor.h).
// cook, neubert and ellipsoids draw the full mesh when a tree is at least `full_pixels` tall on screen.
// Levels are cached: counts and lambdas are rounded up to `steps_per_octave` steps per halving,
// so a frame of many instances builds a few models per tree, not one per instance.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "lod/ellipsoid_clusters.h"
#include "lod/occlusion_factor.h"
#include "lod/point_line_hierarchy.h"

namespace voltree {

enum class MeshLodMethod { kMesh, kPoints, kEllipsoids, kCook, kNeubert };

std::optional<MeshLodMethod> MeshLodMethodFromName(std::string_view name);
const char* MeshLodMethodName(MeshLodMethod method);
std::string MeshLodMethodList();  // "mesh, points, ellipsoids, cook, neubert"

struct MeshLodOptions {
  MeshLodMethod method = MeshLodMethod::kMesh;
  double full_pixels = 512;  // cook, neubert, ellipsoids: trees this tall on screen or taller are the full mesh
  double min_lambda = 0.01;  // cook, neubert: the smallest fraction of leaves a screen size keeps
  uint64_t seed = 1;         // the leaf order, the point sampling and the EM start
  int steps_per_octave = 2;  // cached levels per halving of the primitives
  PointLineOptions points;
  EllipsoidClusterOptions ellipsoids;
  OcclusionOptions occlusion;  // neubert
  // The ellipsoids' semi-axes scale: lod-bench calibrates it by image error per tree and size
  // (docs/lod_ellipsoids.md: 0.58-0.69 on the oak); a scene takes one value.
  double ellipsoid_scale = 0.6;
  int supersample = 1;  // samples per pixel and axis, box-filtered
  // Throws OptionError naming the field.
  void Check() const;
};

}  // namespace voltree
