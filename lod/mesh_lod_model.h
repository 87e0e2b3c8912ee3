// One tree mesh of a scene prepared for a mesh LOD method (lod/mesh_lod_options.h): what the
// method needs, built once (the leaves and their random or priority order, the crown's hull
// samples; the points and lines; the EM levels and the line merges), the level each screen size draws, and the GPU
// models of the levels drawn so far, shared by every instance of the tree. A method that cannot be built for the mesh
// (no leaves, no bark) says so in notes() and draws what it can, else the full mesh.
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "core/camera.h"
#include "lod/crown_samples.h"
#include "lod/ellipsoid_clusters.h"
#include "lod/leaf_separation.h"
#include "lod/line_simplification.h"
#include "lod/mesh_lod_options.h"
#include "lod/point_line_hierarchy.h"
#include "lod/primitive_renderer.h"
#include "render/scene_renderer.h"
#include "samples/studio_lighting.h"
#include "samples/studio_tree_renderer.h"
#include "samples/tree_mesh.h"

namespace voltree {

// What one instance draws.
struct MeshLodLevel {
  bool full = true;              // the full mesh
  double lambda = 1;             // cook, neubert: the fraction of leaves kept
  bool occluded = false;         // neubert: lambda lowered because other trees hide this one
  size_t points = 0, lines = 0;  // points: the prefix of each
  float point_pixels = 1;        // points: the splat side for this instance's distance
  int ellipsoid_level = -1;      // ellipsoids: index into the levels; -1: none (no leaves)
  size_t line_merges = 0;        // ellipsoids: the branch merges applied
};

// The cached count for `wanted` of `total`: the smallest ceil(total * 2^(-k / steps)) that is at
// least `wanted` (0 for 0; total when wanted >= total).
size_t QuantisedCount(size_t wanted, size_t total, int steps);

// The largest 2^(-k / steps) that is at least `lambda` (in (0, 1]).
double QuantisedLambda(double lambda, int steps);

class MeshLodModel {
 public:
  // `name` prefixes the notes. Builds the method's hierarchy; GPU models come with Prepare.
  MeshLodModel(const TreeMesh& mesh, const std::string& name, const MeshLodOptions& options);
  MeshLodModel(const MeshLodModel&) = delete;
  MeshLodModel& operator=(const MeshLodModel&) = delete;

  const std::vector<std::string>& notes() const { return notes_; }
  double preprocess_seconds() const { return preprocess_seconds_; }
  // The box of the mesh in its own frame: culling, depth and the screen size.
  const Eigen::Vector3d& lo() const { return lo_; }
  const Eigen::Vector3d& hi() const { return hi_; }

  // Neubert's occlusion test points on the crown hull (mesh frame); empty for other methods.
  const std::vector<CrownSample>& crown_samples() const { return crown_samples_; }

  // The level a tree drawn `pixels_per_unit` (pixels per mesh unit at its distance) gets;
  // neubert: with `visible` the smoothed visible fraction f of its crown (1: unoccluded).
  MeshLodLevel Choose(double pixels_per_unit, double visible = 1) const;
  // Builds the GPU model `level` draws, once (needs a current GL context).
  void Prepare(const MeshLodLevel& level);
  // Draws a prepared level with `view` and `lighting` in the mesh's frame; what was drawn.
  MeshFrameCounts Draw(const MeshLodLevel& level, const View& view, const StudioLighting& lighting, double near,
                       double far) const;
  // The GPU models built so far: buffers, and the textures of the mesh models.
  GpuMemory GpuBytes() const;

 private:
  using Key = std::tuple<int, size_t, size_t>;
  struct Model {
    std::unique_ptr<StudioTreeRenderer> mesh;
    std::unique_ptr<PrimitiveRenderer> primitives;
    MeshFrameCounts counts;
    GpuMemory bytes;
  };
  Key KeyOf(const MeshLodLevel& level) const;
  Model Build(const MeshLodLevel& level) const;
  Model MeshModel(const TreeMesh& mesh) const;

  MeshLodOptions options_;
  TreeMesh mesh_;
  Eigen::Vector3d lo_, hi_;
  std::pair<Eigen::Vector3f, Eigen::Vector3f> crown_;
  std::vector<Leaf> leaves_;
  std::vector<uint32_t> order_;             // cook: random; neubert: rendering priority
  std::vector<CrownSample> crown_samples_;  // neubert
  PointLineHierarchy point_lines_;          // points
  std::vector<EllipsoidLevel> levels_;      // ellipsoids
  LineHierarchy line_hierarchy_;            // ellipsoids
  bool has_lines_ = false;
  bool reduces_ = false;  // whether the method can draw anything but the full mesh
  std::vector<std::string> notes_;
  double preprocess_seconds_ = 0;
  std::map<Key, Model> models_;
};

}  // namespace voltree
