#include "lod/rendering_priority.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

#include "core/error.h"
#include "lod/seeded_random.h"

namespace voltree {
namespace {

// The leaf centres bucketed in cubes of the influence radius: the neighbours of a point within
// the radius are in its cube and the 26 around it.
class CentreGrid {
 public:
  CentreGrid(const std::vector<Leaf>& leaves, double radius) : leaves_(leaves), cell_(radius) {
    for (uint32_t i = 0; i < leaves.size(); ++i) cells_[Key(Cell(leaves[i].centre))].push_back(i);
  }

  // Calls visit(j, squared distance) for every leaf j within the radius of `point`.
  template <typename Visit>
  void ForNeighbours(const Eigen::Vector3f& point, Visit&& visit) const {
    const Eigen::Vector3i c = Cell(point);
    const double r2 = cell_ * cell_;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (uint32_t j : it->second) {
            const double d2 = (leaves_[j].centre - point).cast<double>().squaredNorm();
            if (d2 < r2) visit(j, d2);
          }
        }
  }

 private:
  Eigen::Vector3i Cell(const Eigen::Vector3f& p) const {
    return (p.cast<double>() / cell_).array().floor().cast<int>();
  }
  static int64_t Key(const Eigen::Vector3i& c) {
    return (static_cast<int64_t>(c.x()) * 2097152 + c.y()) * 2097152 + c.z();
  }

  const std::vector<Leaf>& leaves_;
  double cell_;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells_;
};

// One metaball's contribution, eq. 5: (1 - d^2 / r^2)^2 inside the radius.
double Metaball(double squared_distance, double radius) {
  const double t = 1 - squared_distance / (radius * radius);
  return t > 0 ? t * t : 0;
}

// A voxel grid over the leaf centres, padded so that every ball and a layer outside it fit.
struct HullGrid {
  Eigen::Vector3d origin;
  double cell = 1;
  Eigen::Vector3i dims;
  size_t Index(const Eigen::Vector3i& v) const {
    return (static_cast<size_t>(v.z()) * dims.y() + v.y()) * dims.x() + v.x();
  }
  Eigen::Vector3i Voxel(size_t index) const {
    return {static_cast<int>(index % dims.x()), static_cast<int>(index / dims.x() % dims.y()),
            static_cast<int>(index / (static_cast<size_t>(dims.x()) * dims.y()))};
  }
  Eigen::Vector3d Centre(const Eigen::Vector3i& v) const {
    return origin + cell * (v.cast<double>().array() + 0.5).matrix();
  }
  Eigen::Vector3i Containing(const Eigen::Vector3d& p) const {
    return ((p - origin) / cell).array().floor().cast<int>().max(0).min(dims.array() - 1);
  }
  bool Valid(const Eigen::Vector3i& v) const { return (v.array() >= 0).all() && (v.array() < dims.array()).all(); }
  size_t Size() const { return static_cast<size_t>(dims.x()) * dims.y() * dims.z(); }
};

HullGrid MakeHullGrid(const std::vector<Leaf>& leaves, double radius, int voxels_per_radius) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const Leaf& leaf : leaves) {
    lo = lo.cwiseMin(leaf.centre.cast<double>());
    hi = hi.cwiseMax(leaf.centre.cast<double>());
  }
  HullGrid grid;
  grid.cell = radius / voxels_per_radius;
  // Coarsen a grid that would be too large (a crown far wider than tall): at most 2^24 voxels.
  for (;;) {
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(radius + 2 * grid.cell);
    grid.origin = lo - pad;
    grid.dims = ((hi - lo + 2 * pad) / grid.cell).array().ceil().cast<int>().max(1);
    if (grid.Size() <= (size_t{1} << 24)) return grid;
    grid.cell *= 1.5;
  }
}

}  // namespace

void RenderingPriorityOptions::Check() const {
  if (!(radius_fraction > 0 && radius_fraction <= 1))
    FailOption("RenderingPriorityOptions.radius_fraction", "is ", radius_fraction,
               ", outside (0, 1]: it is a fraction of the plant's height");
  if (voxels_per_radius < 1 || voxels_per_radius > 16)
    FailOption("RenderingPriorityOptions.voxels_per_radius", "is ", voxels_per_radius, ", not in 1..16");
  if (!(jitter >= 0 && jitter <= 1)) FailOption("RenderingPriorityOptions.jitter", "is ", jitter, ", outside [0, 1]");
}

std::vector<double> DensitySurvival(const std::vector<Leaf>& leaves, double radius) {
  if (!(radius > 0)) Fail("lod: the metaball radius ", radius, " is not positive");
  const size_t n = leaves.size();
  const CentreGrid grid(leaves, radius);
  std::vector<double> density(n, 0.0);
  for (uint32_t i = 0; i < n; ++i)
    grid.ForNeighbours(leaves[i].centre, [&](uint32_t, double d2) { density[i] += Metaball(d2, radius); });
  // Greedy: the densest leaf now goes next; entries made stale by a neighbour's removal are skipped.
  using Entry = std::pair<double, uint32_t>;
  const auto later = [](const Entry& a, const Entry& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
  for (uint32_t i = 0; i < n; ++i) queue.push({density[i], i});
  std::vector<bool> removed(n, false);
  std::vector<double> survival(n, 1.0);
  size_t step = 0;
  while (!queue.empty()) {
    const auto [value, i] = queue.top();
    queue.pop();
    if (removed[i] || value != density[i]) continue;
    removed[i] = true;
    survival[i] = n > 1 ? static_cast<double>(step) / static_cast<double>(n - 1) : 1.0;
    ++step;
    grid.ForNeighbours(leaves[i].centre, [&](uint32_t j, double d2) {
      if (removed[j]) return;
      density[j] -= Metaball(d2, radius);
      queue.push({density[j], j});
    });
  }
  return survival;
}

std::vector<Eigen::Vector3f> LeafNormals(const TreeMesh& mesh, const std::vector<Leaf>& leaves) {
  std::vector<Eigen::Vector3f> normals;
  normals.reserve(leaves.size());
  for (const Leaf& leaf : leaves) {
    const std::vector<uint32_t>& indices = mesh.groups.at(leaf.group).indices;
    std::vector<Eigen::Vector3f> faces;  // twice the area times the unit normal
    for (uint32_t t : leaf.triangles) {
      const Eigen::Vector3f& a = mesh.vertices[indices[3 * t]].position;
      const Eigen::Vector3f ab = mesh.vertices[indices[3 * t + 1]].position - a;
      const Eigen::Vector3f ac = mesh.vertices[indices[3 * t + 2]].position - a;
      faces.push_back(ab.cross(ac));
    }
    Eigen::Vector3f reference = Eigen::Vector3f::Zero();
    for (const Eigen::Vector3f& face : faces)
      if (face.squaredNorm() > reference.squaredNorm()) reference = face;
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    for (const Eigen::Vector3f& face : faces) sum += face.dot(reference) < 0 ? -face : face;
    normals.push_back(sum.norm() > 0 ? sum.normalized() : Eigen::Vector3f::UnitZ());
  }
  return normals;
}

std::vector<Eigen::Vector3f> HullNormals(const std::vector<Leaf>& leaves, double radius, int voxels_per_radius) {
  if (leaves.empty()) return {};
  if (!(radius > 0)) Fail("lod: the metaball radius ", radius, " is not positive");
  const HullGrid grid = MakeHullGrid(leaves, radius, voxels_per_radius);
  // Inside the hull: within the radius of a leaf centre (F > 0, the iso-value a = 0).
  std::vector<bool> inside(grid.Size(), false);
  const int reach = static_cast<int>(std::ceil(radius / grid.cell));
  for (const Leaf& leaf : leaves) {
    const Eigen::Vector3d c = leaf.centre.cast<double>();
    const Eigen::Vector3i centre = grid.Containing(c);
    for (int dz = -reach; dz <= reach; ++dz)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const Eigen::Vector3i v = centre + Eigen::Vector3i(dx, dy, dz);
          if (grid.Valid(v) && (grid.Centre(v) - c).squaredNorm() < radius * radius) inside[grid.Index(v)] = true;
        }
  }
  // Each inside voxel's nearest outside voxel, propagated from the outside voxels that touch the
  // hull, nearest first (Dijkstra on the distance to the carried source).
  constexpr size_t kNone = std::numeric_limits<size_t>::max();
  std::vector<size_t> source(grid.Size(), kNone);
  std::vector<double> distance(grid.Size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  const auto for_neighbours = [&](const Eigen::Vector3i& v, auto&& visit) {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (const Eigen::Vector3i u = v + Eigen::Vector3i(dx, dy, dz); (dx || dy || dz) && grid.Valid(u))
            visit(grid.Index(u));
  };
  for (size_t i = 0; i < grid.Size(); ++i) {
    if (inside[i]) continue;
    bool touches = false;
    for_neighbours(grid.Voxel(i), [&](size_t u) { touches = touches || inside[u]; });
    if (touches) source[i] = i, distance[i] = 0, queue.push({0.0, i});
  }
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > distance[i]) continue;
    const Eigen::Vector3d from = grid.Centre(grid.Voxel(source[i]));
    for_neighbours(grid.Voxel(i), [&](size_t u) {
      if (!inside[u]) return;
      const double candidate = (grid.Centre(grid.Voxel(u)) - from).norm();
      if (candidate < distance[u]) distance[u] = candidate, source[u] = source[i], queue.push({candidate, u});
    });
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Leaf& leaf : leaves) mean += leaf.centre.cast<double>();
  mean /= static_cast<double>(leaves.size());
  std::vector<Eigen::Vector3f> normals;
  normals.reserve(leaves.size());
  for (const Leaf& leaf : leaves) {
    const Eigen::Vector3d c = leaf.centre.cast<double>();
    const size_t nearest = source[grid.Index(grid.Containing(c))];
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    if (nearest != kNone) normal = grid.Centre(grid.Voxel(nearest)) - c;
    if (normal.norm() == 0) normal = c - mean;  // not reached by the propagation: radial
    normals.push_back(normal.norm() > 0 ? Eigen::Vector3f(normal.normalized().cast<float>())
                                        : Eigen::Vector3f::UnitZ());
  }
  return normals;
}

std::vector<double> SilhouetteSurvival(const std::vector<Eigen::Vector3f>& leaf_normals,
                                       const std::vector<Eigen::Vector3f>& hull_normals) {
  if (leaf_normals.size() != hull_normals.size())
    Fail("lod: ", leaf_normals.size(), " leaf normals against ", hull_normals.size(), " hull normals");
  std::vector<double> survival(leaf_normals.size());
  for (size_t i = 0; i < survival.size(); ++i)
    survival[i] = std::min(1.0, static_cast<double>(std::abs(leaf_normals[i].dot(hull_normals[i]))));
  return survival;
}

std::vector<double> CombinedSurvival(const std::vector<double>& silhouette, const std::vector<double>& density) {
  if (silhouette.size() != density.size())
    Fail("lod: ", silhouette.size(), " silhouette terms against ", density.size(), " density terms");
  std::vector<double> combined(silhouette.size());
  for (size_t i = 0; i < combined.size(); ++i) combined[i] = silhouette[i] * silhouette[i] + density[i];
  if (combined.empty()) return combined;
  const auto [lo, hi] = std::minmax_element(combined.begin(), combined.end());
  const double low = *lo, range = *hi - *lo;
  for (double& value : combined) value = range > 0 ? (value - low) / range : 0.0;
  return combined;
}

std::vector<uint32_t> PriorityLeafOrder(const std::vector<double>& survival, double jitter, uint64_t seed) {
  SeededRandom random(seed);
  std::vector<double> key(survival.size());
  for (size_t i = 0; i < key.size(); ++i) key[i] = survival[i] + jitter * random.Uniform();
  std::vector<uint32_t> order(survival.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key[a] > key[b]; });
  return order;
}

std::vector<uint32_t> RenderingPriorityOrder(const TreeMesh& mesh, const std::vector<Leaf>& leaves,
                                             const RenderingPriorityOptions& options) {
  options.Check();
  if (leaves.empty()) return {};
  const auto [lo, hi] = mesh.Bounds();
  const Eigen::Vector3f extent = hi - lo;
  const double height = extent.z() > 0 ? extent.z() : extent.maxCoeff();
  const double radius = options.radius_fraction * std::max(height, 1e-6);
  const auto silhouette = [&] {
    return SilhouetteSurvival(LeafNormals(mesh, leaves), HullNormals(leaves, radius, options.voxels_per_radius));
  };
  const std::vector<double> survival = options.terms == PriorityTerms::kSilhouette ? silhouette()
                                       : options.terms == PriorityTerms::kDensity
                                           ? DensitySurvival(leaves, radius)
                                           : CombinedSurvival(silhouette(), DensitySurvival(leaves, radius));
  return PriorityLeafOrder(survival, options.jitter, options.seed);
}

}  // namespace voltree
