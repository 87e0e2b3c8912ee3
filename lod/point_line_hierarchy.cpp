#include "lod/point_line_hierarchy.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "lod/seeded_random.h"
#include "lod/surface_colour.h"

namespace voltree {
namespace {

struct LeafTriangle {
  int group = 0;
  uint32_t triangle = 0;
};

// A point on the triangle, uniform by area, with its normal and colour; `alpha` the texel's.
PointPrimitive SamplePoint(const TreeMesh& mesh, const LeafTriangle& where, SeededRandom& random, float* alpha) {
  const MeshGroup& group = mesh.groups[where.group];
  const MeshVertex& a = mesh.vertices[group.indices[3 * where.triangle]];
  const MeshVertex& b = mesh.vertices[group.indices[3 * where.triangle + 1]];
  const MeshVertex& c = mesh.vertices[group.indices[3 * where.triangle + 2]];
  double u = random.Uniform(), v = random.Uniform();
  if (u + v > 1) u = 1 - u, v = 1 - v;
  const auto fu = static_cast<float>(u), fv = static_cast<float>(v), fw = 1 - fu - fv;
  PointPrimitive point;
  point.position = fw * a.position + fu * b.position + fv * c.position;
  const Eigen::Vector3f normal = (b.position - a.position).cross(c.position - a.position);
  point.normal = normal.norm() > 0 ? Eigen::Vector3f(normal.normalized()) : Eigen::Vector3f::UnitZ();
  const Eigen::Vector4f texel = MaterialSample(mesh, group.material, fw * a.uv + fu * b.uv + fv * c.uv);
  point.colour = texel.head<3>().cwiseProduct(fw * a.tint + fu * b.tint + fv * c.tint);
  *alpha = texel[3];
  return point;
}

double TriangleArea(const TreeMesh& mesh, const LeafTriangle& where) {
  const MeshGroup& group = mesh.groups[where.group];
  const Eigen::Vector3f& a = mesh.vertices[group.indices[3 * where.triangle]].position;
  const Eigen::Vector3f& b = mesh.vertices[group.indices[3 * where.triangle + 1]].position;
  const Eigen::Vector3f& c = mesh.vertices[group.indices[3 * where.triangle + 2]].position;
  return 0.5 * static_cast<double>((b - a).cross(c - a).norm());
}

}  // namespace

void PointLineOptions::Check() const {
  if (points_per_triangle < 1)
    FailOption("PointLineOptions.points_per_triangle", "is ", points_per_triangle, ", not >= 1");
  if (alpha_tries < 1) FailOption("PointLineOptions.alpha_tries", "is ", alpha_tries, ", not >= 1");
  if (!(sample_distance > 0))
    FailOption("PointLineOptions.sample_distance", "is ", sample_distance, ": give a distance in pixels > 0");
  if (!(splat_factor > 0)) FailOption("PointLineOptions.splat_factor", "is ", splat_factor, ", not > 0");
  if (!(min_line_pixels > 0)) FailOption("PointLineOptions.min_line_pixels", "is ", min_line_pixels, ", not > 0");
}

PointLineHierarchy BuildPointLineHierarchy(const TreeMesh& mesh, const std::vector<Leaf>& leaves,
                                           const BranchSkeleton& skeleton, const PointLineOptions& options) {
  options.Check();
  PointLineHierarchy hierarchy;
  // Points: triangles drawn by area (equal surfaces, equal numbers of points), each point tried
  // again inside the same triangle until it lands on the opaque part of the card.
  std::vector<LeafTriangle> triangles;
  std::vector<double> cumulative;
  double card_area = 0;
  for (const Leaf& leaf : leaves)
    for (uint32_t triangle : leaf.triangles) {
      triangles.push_back({leaf.group, triangle});
      card_area += TriangleArea(mesh, triangles.back());
      cumulative.push_back(card_area);
    }
  SeededRandom random(options.seed);
  const size_t wanted = triangles.size() * static_cast<size_t>(options.points_per_triangle);
  size_t tries = 0, hits = 0;
  for (size_t i = 0; i < wanted && card_area > 0; ++i) {
    const double pick = random.Uniform() * card_area;
    const size_t t = std::min<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
                                      triangles.size() - 1);
    const float cutoff = std::max(AlphaCutoff(mesh.materials[mesh.groups[triangles[t].group].material]), 0.0f);
    for (int attempt = 0; attempt < options.alpha_tries; ++attempt) {
      float alpha = 1;
      const PointPrimitive point = SamplePoint(mesh, triangles[t], random, &alpha);
      ++tries;
      if (alpha >= cutoff) {
        hierarchy.points.push_back(point);
        ++hits;
        break;
      }
    }
  }
  // The share of tries that landed inside the cut-out estimates the visible share of the cards.
  hierarchy.leaf_area = tries > 0 ? card_area * static_cast<double>(hits) / static_cast<double>(tries) : 0;

  // Lines: largest projected area first, so that the trunk is the last to go.
  hierarchy.lines = SkeletonLines(skeleton);
  std::stable_sort(hierarchy.lines.begin(), hierarchy.lines.end(), [](const LinePrimitive& a, const LinePrimitive& b) {
    return (a.b - a.a).norm() * a.width > (b.b - b.a).norm() * b.width;
  });
  return hierarchy;
}

PointLineHierarchy PointLinePrefix(const PointLineHierarchy& hierarchy, size_t points, size_t lines) {
  PointLineHierarchy prefix;
  prefix.points.assign(hierarchy.points.begin(), hierarchy.points.begin() + std::min(points, hierarchy.points.size()));
  prefix.lines.assign(hierarchy.lines.begin(), hierarchy.lines.begin() + std::min(lines, hierarchy.lines.size()));
  prefix.leaf_area = hierarchy.leaf_area;
  return prefix;
}

PointLineLevel PointLineLevelFor(const PointLineHierarchy& hierarchy, double pixels_per_unit,
                                 const PointLineOptions& options) {
  options.Check();
  if (!(pixels_per_unit > 0)) Fail("lod: pixels per unit ", pixels_per_unit, " is not positive");
  PointLineLevel level;
  // Eq. 1: the leaves' projected area (1/2 for random orientation) over d'^2.
  const double leaf_pixels = 0.5 * hierarchy.leaf_area * pixels_per_unit * pixels_per_unit;
  const double d2 = options.sample_distance * options.sample_distance;
  const auto wanted = static_cast<size_t>(std::ceil(leaf_pixels / d2));
  if (wanted > hierarchy.points.size() && !hierarchy.points.empty()) {
    level.polygons = true;
    return level;
  }
  level.points = std::min(wanted, hierarchy.points.size());
  if (level.points > 0)
    level.point_pixels = static_cast<float>(std::sqrt(options.splat_factor * leaf_pixels / level.points));
  // Eq. 2: lines until their drawn area reaches the branches' projected area.
  double true_area = 0;
  for (const LinePrimitive& line : hierarchy.lines) true_area += (line.b - line.a).norm() * line.width;
  true_area *= pixels_per_unit * pixels_per_unit;
  double drawn = 0;
  for (const LinePrimitive& line : hierarchy.lines) {
    const double length = (line.b - line.a).norm() * pixels_per_unit;
    drawn += length * std::max(line.width * pixels_per_unit, options.min_line_pixels);
    if (level.lines > 0 && drawn > true_area) break;
    ++level.lines;
  }
  return level;
}

}  // namespace voltree
