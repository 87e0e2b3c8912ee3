// Neubert et al. 2011's rendering priority (sec. 3): instead of Cook's random order, the leaves are
// ranked by "survival probabilities" from a global density function of metaballs at the leaf
// centres (their eq. 5, radius 5 % of the plant's height), whose zero iso-surface is the crown's
// tight hull:
//  - density normalization (sec. 3.1.1): leaves in dense regions go first, since their pixels are
//    likely covered by their neighbours anyway;
//  - silhouette, by orientation (sec. 3.2): leaves that face the way the hull faces at its nearest
//    point (small angle alpha) stay longest; enlarged, they resemble the hull and cover what the
//    full crown covers;
//  - combined (sec. 3.3): P = P_silhouette^2 + P_density, normalized to [0, 1], plus a little
//    randomness, sorted descending. The paper's tables name the orientation heuristic
//    "Silhouette"; keeping leaves merely near the hull it found inferior, so that is not a term.
#pragma once

#include <cstdint>
#include <vector>

#include "lod/leaf_separation.h"
#include "samples/tree_mesh.h"

namespace voltree {

// Which survival probability orders the leaves: the paper compares each heuristic alone with the
// combination (its table 2 and fig. 8).
enum class PriorityTerms { kCombined, kSilhouette, kDensity };

struct RenderingPriorityOptions {
  PriorityTerms terms = PriorityTerms::kCombined;
  double radius_fraction = 0.05;  // metaball influence radius, of the plant's height (paper: 5 %)
  int voxels_per_radius = 3;      // the hull's voxel grid: cells per influence radius
  double jitter = 0.05;           // "a small amount of randomness", added to P in [0, 1] before sorting
  uint64_t seed = 1;              // the jitter's

  // Throws OptionError naming the field.
  void Check() const;
};

// Density normalization's survival in [0, 1]: the leaves' position in a greedy removal that always
// takes the leaf where the density F (eq. 5) is highest now, updating its neighbours' F as it goes
// (0: removed first, 1: removed last). Once the density is even this keeps thinning it evenly,
// where the paper switches to random order.
std::vector<double> DensitySurvival(const std::vector<Leaf>& leaves, double radius);

// Each leaf's unit normal (area-weighted, sides aligned with its largest triangle's).
std::vector<Eigen::Vector3f> LeafNormals(const TreeMesh& mesh, const std::vector<Leaf>& leaves);

// The hull's outward normal at the point nearest each leaf centre: the hull is the union of the
// metaballs (iso-value 0), voxelized at radius / voxels_per_radius, its nearest outside voxel found
// by a vector-propagating distance transform.
std::vector<Eigen::Vector3f> HullNormals(const std::vector<Leaf>& leaves, double radius, int voxels_per_radius);

// Orientation's survival |cos alpha| in [0, 1] (leaf cards are two-sided).
std::vector<double> SilhouetteSurvival(const std::vector<Eigen::Vector3f>& leaf_normals,
                                       const std::vector<Eigen::Vector3f>& hull_normals);

// P_silhouette^2 + P_density, scaled to [0, 1] by its range. Throws Error on a size mismatch.
std::vector<double> CombinedSurvival(const std::vector<double>& silhouette, const std::vector<double>& density);

// The leaves sorted by descending survival + jitter * uniform noise (ties by index): a priority
// order as RandomLeafOrder's, drawn by its prefix.
std::vector<uint32_t> PriorityLeafOrder(const std::vector<double>& survival, double jitter, uint64_t seed);

// All of the above for a mesh: the order by `options.terms` (the combined one by default). The radius is
// radius_fraction of the mesh's height (its z extent: the tree frame is +Z up).
std::vector<uint32_t> RenderingPriorityOrder(const TreeMesh& mesh, const std::vector<Leaf>& leaves,
                                             const RenderingPriorityOptions& options);

}  // namespace voltree
