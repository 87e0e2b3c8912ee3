// Clustered ellipsoids (Clasen, Paar and Prohaska, "Level of detail for trees using clustered
// ellipsoids"), the leaves' part: Expectation Maximization on a Gaussian mixture over the leaf
// centres (weighted by leaf area) gives one clustering per level, 1, 4, 16, ... clusters (the paper
// divides by 4 from a quarter of the leaves down to 1; here from `max_clusters`); each cluster
// becomes an ellipsoid by a PCA of the centres weighted by the fuzzy assignments (sec. 3.1), in
// the cluster's mean leaf colour. A screen size draws the finest level whose ellipsoids are at
// least `min_pixels` across on average (sec. 6: 5 pixels by default).
//
// Where we depart: one EM run per level from a seeded k-means++ start, instead of the paper's
// best of several random starts chosen by image error; no noise texture (alpha holes and normal
// noise), the ellipsoids are plain shaded surfaces; their size is the PCA's (a solid ellipsoid of
// the same second moments, semi-axes sqrt(5 lambda)) grown by half a leaf, not calibrated by
// image error.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lod/leaf_separation.h"
#include "lod/primitive_renderer.h"

namespace voltree {

struct EllipsoidClusterOptions {
  int max_clusters = 256;           // the finest level (fewer when there are fewer leaves)
  int level_factor = 4;             // clusters of a level over those of the next coarser one
  int iterations = 40;              // EM iterations at most per level
  double tolerance = 1e-5;          // stop when the log-likelihood changes less, relatively
  uint64_t seed = 1;                // the k-means++ start
  double min_pixels = 5;            // the mean ellipsoid diameter on screen a level must keep
  double min_area_fraction = 0.01;  // ellipsoids smaller than this of the level's largest are dropped
  int sphere_segments = 12;         // the drawn ellipsoid: a unit sphere of 12 x 6 quads, stretched

  // Throws OptionError naming the field.
  void Check() const;
};

struct GaussianComponent {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  double weight = 0;  // mixing weight, summing to 1
};

struct GaussianMixture {
  std::vector<GaussianComponent> components;
  std::vector<std::vector<double>> responsibilities;  // [point][component], rows summing to 1
  int iterations = 0;
  double log_likelihood = 0;
};

// EM from a seeded k-means++ start. `weights`: one per point, > 0. Throws Error when there are
// fewer points than `clusters` or `clusters` < 1.
GaussianMixture FitGaussianMixture(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                                   int clusters, const EllipsoidClusterOptions& options);

struct Ellipsoid {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();  // columns: the semi-axes
  Eigen::Vector3f colour = Eigen::Vector3f::Ones();    // linear RGB
};

struct EllipsoidLevel {
  int clusters = 0;  // asked of EM
  std::vector<Ellipsoid> ellipsoids;
};

// Coarsest level first. Levels stop at the number of leaves; none without leaves.
std::vector<EllipsoidLevel> BuildEllipsoidHierarchy(const std::vector<Leaf>& leaves,
                                                    const std::vector<Eigen::Vector3f>& colours,
                                                    const EllipsoidClusterOptions& options);

// The index of the level a tree `pixels_per_unit` on screen draws.
size_t EllipsoidLevelFor(const std::vector<EllipsoidLevel>& levels, double pixels_per_unit, double min_pixels);

// The ellipsoids as triangles (three corners each), outward normals.
std::vector<PointPrimitive> EllipsoidSurface(const std::vector<Ellipsoid>& ellipsoids, int segments);

}  // namespace voltree
