// Points and lines for distant plants (Deussen, Colditz, Stamminger and Drettakis 2002): the
// leaves are sampled into points, spread over the leaf surface so that equal areas get equal
// numbers (2 per leaf triangle by default, sec. 4.1) and kept in the random order they were drawn
// in, so any prefix is a uniform sample; the branches become lines (sec. 4.2), here the segments
// of the skeleton recovered from the bark, largest projected area first. A screen size asks for a
// prefix of each list (sec. 5.1-5.2): as many points as the leaves' projected area holds at the
// sampling distance d' (eq. 1), splats of side sqrt(splat factor) * d', and lines until their
// drawn area (at least `min_line_pixels` wide) matches the branches' projected area (eq. 2). When
// the points asked for exceed those sampled, the tree is drawn as polygons instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lod/branch_skeleton.h"
#include "lod/leaf_separation.h"
#include "lod/primitive_renderer.h"
#include "samples/tree_mesh.h"

namespace voltree {

struct PointLineOptions {
  int points_per_triangle = 2;  // sampled points per leaf triangle (the paper's 2n for n triangles)
  int alpha_tries = 8;          // tries per point to land inside the leaf's cut-out (alpha test)
  uint64_t seed = 1;            // the sampling, hence the order
  double sample_distance = 1;   // d', pixels between neighbouring points on screen
  double splat_factor = 1.3;    // splat area over d'^2 (the paper: 1.2 to 1.5)
  double min_line_pixels = 1;   // the narrowest line drawn

  // Throws OptionError naming the field (counts below 1, distances and factors not positive).
  void Check() const;
};

struct PointLineHierarchy {
  std::vector<PointPrimitive> points;  // in sampling order: a prefix is a uniform sample
  std::vector<LinePrimitive> lines;    // largest length * width first
  double leaf_area = 0;                // one-sided leaf area inside the cut-outs (what the points cover)
};

PointLineHierarchy BuildPointLineHierarchy(const TreeMesh& mesh, const std::vector<Leaf>& leaves,
                                           const BranchSkeleton& skeleton, const PointLineOptions& options);

// The first `points` points and `lines` lines (fewer when there are fewer).
PointLineHierarchy PointLinePrefix(const PointLineHierarchy& hierarchy, size_t points, size_t lines);

// What a tree `pixels_per_unit` on screen (pixels per mesh unit at its distance) draws.
struct PointLineLevel {
  bool polygons = false;  // more points asked for than sampled: draw the mesh
  size_t points = 0, lines = 0;
  float point_pixels = 1;  // splat side, output pixels
};
PointLineLevel PointLineLevelFor(const PointLineHierarchy& hierarchy, double pixels_per_unit,
                                 const PointLineOptions& options);

}  // namespace voltree
