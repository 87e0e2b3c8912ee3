#include "lod/mesh_lod_model.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "lod/branch_skeleton.h"
#include "lod/pruned_mesh.h"
#include "lod/rendering_priority.h"
#include "lod/screen_size_rule.h"
#include "lod/stochastic_pruning.h"
#include "lod/surface_colour.h"

namespace voltree {
namespace {

constexpr float kClasenLinePixels = 1;  // Clasen et al.'s default line width (sec. 6)

// The smallest 2^(k / steps) that is at least `value` (> 0): pixels per unit rounded up, so that
// the branch merges a cached level applies move the lines no more than at the exact distance.
double QuantisedUp(double value, int steps) { return std::exp2(std::ceil(std::log2(value) * steps) / steps); }

std::vector<Ellipsoid> Scaled(std::vector<Ellipsoid> ellipsoids, double scale) {
  for (Ellipsoid& ellipsoid : ellipsoids) ellipsoid.axes *= static_cast<float>(scale);
  return ellipsoids;
}

}  // namespace

size_t QuantisedCount(size_t wanted, size_t total, int steps) {
  if (wanted == 0) return 0;
  if (wanted >= total) return total;
  size_t count = total;
  for (int k = 1;; ++k) {
    const auto next = static_cast<size_t>(std::ceil(static_cast<double>(total) * std::exp2(-double(k) / steps)));
    if (next < wanted) return count;
    count = next;
  }
}

double QuantisedLambda(double lambda, int steps) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: lambda ", lambda, " is outside (0, 1]");
  int k = static_cast<int>(std::floor(-std::log2(lambda) * steps + 1e-9));
  while (k > 0 && std::exp2(-double(k) / steps) < lambda) --k;
  return std::exp2(-double(k) / steps);
}

MeshLodModel::MeshLodModel(const TreeMesh& mesh, const std::string& name, const MeshLodOptions& options)
    : options_(options), mesh_(mesh), crown_(mesh.CrownBounds()) {
  options_.Check();
  mesh_.Check();
  options_.points.seed = options_.ellipsoids.seed = options_.seed;
  const auto [lo, hi] = mesh_.Bounds();
  lo_ = lo.cast<double>(), hi_ = hi.cast<double>();
  const auto start = std::chrono::steady_clock::now();
  const char* method = MeshLodMethodName(options_.method);
  if (options_.method != MeshLodMethod::kMesh) leaves_ = SeparateLeaves(mesh_);
  const std::string no_leaves = Str(name, ": no separable leaves (no alpha-tested or blended material): ", method);
  switch (options_.method) {
    case MeshLodMethod::kMesh:
      break;
    case MeshLodMethod::kCook:
      if (leaves_.empty()) notes_.push_back(no_leaves + " needs leaves; drawn as the full mesh");
      order_ = RandomLeafOrder(leaves_.size(), options_.seed);
      reduces_ = !leaves_.empty();
      break;
    case MeshLodMethod::kNeubert: {
      if (leaves_.empty()) notes_.push_back(no_leaves + " needs leaves; drawn as the full mesh");
      RenderingPriorityOptions priority;
      priority.seed = options_.seed;
      order_ = RenderingPriorityOrder(mesh_, leaves_, priority);
      // The hull of the priority's metaballs (radius a fraction of the height, as there).
      crown_samples_ = CrownHullSamples(leaves_, priority.radius_fraction * std::max((hi_ - lo_).z(), 1e-6),
                                        options_.occlusion.samples, options_.seed);
      reduces_ = !leaves_.empty();
      break;
    }
    case MeshLodMethod::kPoints:
    case MeshLodMethod::kEllipsoids: {
      const BranchSkeleton skeleton = ExtractBranchSkeleton(mesh_);
      has_lines_ = skeleton.SegmentCount() > 0;
      reduces_ = !leaves_.empty() || has_lines_;
      if (!reduces_)
        notes_.push_back(no_leaves +
                         " needs leaves or bark, and there is too little bark for a branch line; drawn "
                         "as the full mesh");
      else if (leaves_.empty())
        notes_.push_back(no_leaves + " draws only the branch lines");
      else if (!has_lines_)
        notes_.push_back(
            Str(name, ": no bark to make branch lines of: ", method, " draws only the leaves' primitives"));
      if (!reduces_) break;
      if (options_.method == MeshLodMethod::kPoints) {
        point_lines_ = BuildPointLineHierarchy(mesh_, leaves_, skeleton, options_.points);
      } else {
        if (!leaves_.empty())
          levels_ = BuildEllipsoidHierarchy(leaves_, LeafColours(mesh_, leaves_), options_.ellipsoids);
        if (has_lines_) line_hierarchy_ = SimplifyLines(skeleton);
      }
      break;
    }
  }
  preprocess_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

MeshLodLevel MeshLodModel::Choose(double pixels_per_unit, double visible) const {
  if (!(pixels_per_unit > 0)) Fail("lod: pixels per unit ", pixels_per_unit, " is not positive");
  if (!(visible >= 0 && visible <= 1)) Fail("lod: visible fraction ", visible, " is outside [0, 1]");
  MeshLodLevel level;
  if (!reduces_) return level;
  const double size = pixels_per_unit * (hi_ - lo_).z();  // the tree's height on screen
  const bool near = size >= options_.full_pixels;
  switch (options_.method) {
    case MeshLodMethod::kMesh:
      break;
    case MeshLodMethod::kCook:
      if (near) break;
      level.lambda = QuantisedLambda(LambdaForScreenSize(size, options_.full_pixels, options_.min_lambda),
                                     options_.steps_per_octave);
      level.full = level.lambda >= 1;
      break;
    case MeshLodMethod::kNeubert: {
      // Occlusion lowers the level of near trees too: lambda(d) is 1 there.
      const double lambda = near ? 1.0 : LambdaForScreenSize(size, options_.full_pixels, options_.min_lambda);
      const double unoccluded = QuantisedLambda(lambda, options_.steps_per_octave);
      level.lambda =
          QuantisedLambda(OccludedLambda(lambda, visible, options_.occlusion.min_factor), options_.steps_per_octave);
      level.occluded = level.lambda < unoccluded;
      level.full = level.lambda >= 1;
      break;
    }
    case MeshLodMethod::kPoints: {
      const PointLineLevel wanted = PointLineLevelFor(point_lines_, pixels_per_unit, options_.points);
      if (wanted.polygons) break;  // Deussen et al.: more points asked for than sampled
      level.full = false;
      level.points = QuantisedCount(wanted.points, point_lines_.points.size(), options_.steps_per_octave);
      level.lines = QuantisedCount(wanted.lines, point_lines_.lines.size(), options_.steps_per_octave);
      // The splats of more points than asked are smaller, so that they cover the same area.
      if (level.points > 0)
        level.point_pixels = wanted.point_pixels * static_cast<float>(std::sqrt(double(wanted.points) / level.points));
      break;
    }
    case MeshLodMethod::kEllipsoids:
      if (near) break;
      level.full = false;
      if (!levels_.empty())
        level.ellipsoid_level =
            static_cast<int>(EllipsoidLevelFor(levels_, pixels_per_unit, options_.ellipsoids.min_pixels));
      if (has_lines_)
        level.line_merges = MergesWithin(line_hierarchy_, 1 / QuantisedUp(pixels_per_unit, options_.steps_per_octave));
      break;
  }
  return level;
}

MeshLodModel::Key MeshLodModel::KeyOf(const MeshLodLevel& level) const {
  if (level.full) return {0, 0, 0};
  switch (options_.method) {
    case MeshLodMethod::kCook:
    case MeshLodMethod::kNeubert:
      return {1, static_cast<size_t>(std::llround(-std::log2(level.lambda) * options_.steps_per_octave)), 0};
    case MeshLodMethod::kPoints:
      return {2, level.points, level.lines};
    default:
      return {3, static_cast<size_t>(level.ellipsoid_level + 1), level.line_merges};
  }
}

MeshLodModel::Model MeshLodModel::MeshModel(const TreeMesh& mesh) const {
  Model model;
  model.mesh = std::make_unique<StudioTreeRenderer>(mesh);
  model.counts.triangles = mesh.TriangleCount();
  // As the studio uploads them: position, normal, uv and tint per vertex; 32-bit indices; RGBA8.
  model.bytes.buffers = mesh.vertices.size() * 11 * sizeof(float) + mesh.TriangleCount() * 3 * sizeof(uint32_t);
  for (const Image8& texture : mesh.textures)
    model.bytes.atlas += texture.pixels.size() / std::max(texture.channels, 1) * 4;
  return model;
}

MeshLodModel::Model MeshLodModel::Build(const MeshLodLevel& level) const {
  if (level.full) return MeshModel(mesh_);
  if (options_.method == MeshLodMethod::kCook || options_.method == MeshLodMethod::kNeubert)
    return MeshModel(BuildPrunedMesh(mesh_, leaves_, PruneLeaves(order_, level.lambda, CookAreaScale(level.lambda))));
  Model model;
  std::vector<PointPrimitive> points, surface;
  std::vector<LinePrimitive> lines;
  if (options_.method == MeshLodMethod::kPoints) {
    const PointLineHierarchy prefix = PointLinePrefix(point_lines_, level.points, level.lines);
    points = prefix.points;
    lines = prefix.lines;
  } else {
    if (level.ellipsoid_level >= 0) {
      const EllipsoidLevel& chosen = levels_[level.ellipsoid_level];
      surface =
          EllipsoidSurface(Scaled(chosen.ellipsoids, options_.ellipsoid_scale), options_.ellipsoids.sphere_segments);
      model.counts.ellipsoids = chosen.ellipsoids.size();
    }
    if (has_lines_) lines = SkeletonLines(LinesAfter(line_hierarchy_, level.line_merges));
  }
  model.primitives = std::make_unique<PrimitiveRenderer>(points, lines, crown_.first, crown_.second, surface);
  model.counts.points = points.size();
  model.counts.lines = lines.size();
  model.counts.triangles = surface.size() / 3 + 2 * lines.size();
  model.bytes.buffers = model.primitives->GpuBytes();
  return model;
}

void MeshLodModel::Prepare(const MeshLodLevel& level) {
  const Key key = KeyOf(level);
  if (!models_.count(key)) models_.emplace(key, Build(level));
}

MeshFrameCounts MeshLodModel::Draw(const MeshLodLevel& level, const View& view, const StudioLighting& lighting,
                                   double near, double far) const {
  const auto found = models_.find(KeyOf(level));
  if (found == models_.end()) Fail("lod: a level was drawn before it was prepared");
  const Model& model = found->second;
  if (model.mesh) {
    model.mesh->Draw(view, lighting, near, far);
  } else {
    PrimitiveDrawOptions draw;
    draw.point_pixels = level.point_pixels;
    draw.min_line_pixels = options_.method == MeshLodMethod::kPoints
                               ? static_cast<float>(options_.points.min_line_pixels)
                               : kClasenLinePixels;
    model.primitives->Draw(view, lighting, near, far, draw);
  }
  MeshFrameCounts counts = model.counts;
  (level.full ? counts.full_instances : counts.reduced_instances) = 1;
  counts.occluded_instances = level.occluded ? 1 : 0;
  return counts;
}

GpuMemory MeshLodModel::GpuBytes() const {
  GpuMemory total;
  for (const auto& [key, model] : models_) total.buffers += model.bytes.buffers, total.atlas += model.bytes.atlas;
  return total;
}

}  // namespace voltree
