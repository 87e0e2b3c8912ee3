#include "lod/ellipsoid_clusters.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "lod/seeded_random.h"

namespace voltree {
namespace {

// k-means++: the first centre drawn by weight, each next one by weight times the squared
// distance to the nearest centre so far.
std::vector<Eigen::Vector3d> KMeansPlusPlus(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<double>& weights, int clusters, uint64_t seed) {
  SeededRandom random(seed);
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
  std::vector<Eigen::Vector3d> centres;
  const auto draw = [&](const std::vector<double>& score) {
    double total = 0;
    for (double s : score) total += s;
    double pick = random.Uniform() * total;
    for (size_t i = 0; i < score.size(); ++i) {
      pick -= score[i];
      if (pick < 0) return i;
    }
    return score.size() - 1;
  };
  centres.push_back(points[draw(weights)]);
  std::vector<double> score(points.size());
  while (static_cast<int>(centres.size()) < clusters) {
    for (size_t i = 0; i < points.size(); ++i) {
      nearest[i] = std::min(nearest[i], (points[i] - centres.back()).squaredNorm());
      score[i] = weights[i] * nearest[i];
    }
    centres.push_back(points[draw(score)]);
  }
  return centres;
}

double EllipsoidArea(const Eigen::Vector3f& radii) {  // Knud Thomsen's approximation
  const double p = 1.6075, a = radii[0], b = radii[1], c = radii[2];
  return 4 * std::numbers::pi * std::pow((std::pow(a * b, p) + std::pow(a * c, p) + std::pow(b * c, p)) / 3, 1 / p);
}

}  // namespace

void EllipsoidClusterOptions::Check() const {
  if (max_clusters < 1) FailOption("EllipsoidClusterOptions.max_clusters", "is ", max_clusters, ", not >= 1");
  if (level_factor < 2) FailOption("EllipsoidClusterOptions.level_factor", "is ", level_factor, ", not >= 2");
  if (iterations < 1) FailOption("EllipsoidClusterOptions.iterations", "is ", iterations, ", not >= 1");
  if (!(tolerance >= 0)) FailOption("EllipsoidClusterOptions.tolerance", "is ", tolerance, ", not >= 0");
  if (!(min_pixels > 0)) FailOption("EllipsoidClusterOptions.min_pixels", "is ", min_pixels, ", not > 0");
  if (!(min_area_fraction >= 0 && min_area_fraction < 1))
    FailOption("EllipsoidClusterOptions.min_area_fraction", "is ", min_area_fraction, ", not in [0, 1)");
  if (sphere_segments < 3) FailOption("EllipsoidClusterOptions.sphere_segments", "is ", sphere_segments, ", not >= 3");
}

GaussianMixture FitGaussianMixture(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                                   int clusters, const EllipsoidClusterOptions& options) {
  options.Check();
  if (clusters < 1) Fail("ellipsoids: asked for ", clusters, " clusters; give at least 1");
  if (points.size() < static_cast<size_t>(clusters))
    Fail("ellipsoids: asked for ", clusters, " clusters of ", points.size(),
         " leaves; a cluster needs at least one leaf");
  if (weights.size() != points.size()) Fail("ellipsoids: ", weights.size(), " weights for ", points.size(), " points");
  const size_t n = points.size();
  const auto k = static_cast<size_t>(clusters);
  double total = 0;
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (size_t i = 0; i < n; ++i) {
    if (!(weights[i] > 0)) Fail("ellipsoids: point ", i, " has weight ", weights[i], ", not > 0");
    total += weights[i];
    lo = lo.cwiseMin(points[i]), hi = hi.cwiseMax(points[i]);
  }
  // A floor on every variance, so that a cluster of one leaf (or of leaves in a plane) stays a
  // proper Gaussian.
  const double floor = std::pow(1e-3 * std::max((hi - lo).norm(), 1e-9), 2);
  Eigen::Vector3d mean_all = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) mean_all += weights[i] * points[i];
  mean_all /= total;
  Eigen::Matrix3d cov_all = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < n; ++i) cov_all += weights[i] * (points[i] - mean_all) * (points[i] - mean_all).transpose();
  cov_all /= total;

  GaussianMixture mixture;
  const std::vector<Eigen::Vector3d> centres = KMeansPlusPlus(points, weights, clusters, options.seed);
  // Start: each Gaussian as wide as the whole set shrunk to its share of the volume.
  const Eigen::Matrix3d start =
      cov_all / std::pow(static_cast<double>(k), 2.0 / 3) + floor * Eigen::Matrix3d::Identity();
  for (const Eigen::Vector3d& centre : centres) mixture.components.push_back({centre, start, 1.0 / k});
  mixture.responsibilities.assign(n, std::vector<double>(k, 0));
  std::vector<double> log_p(k);
  double previous = -std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    // E step, in logs: log(pi_j N(x | mu_j, Sigma_j)) from each Cholesky factor L (the
    // Mahalanobis distance is |L^-1 (x - mu)|).
    std::vector<Eigen::Matrix3d> whiten(k);
    std::vector<double> log_norm(k);
    for (size_t j = 0; j < k; ++j) {
      const GaussianComponent& c = mixture.components[j];
      const Eigen::Matrix3d l = Eigen::LLT<Eigen::Matrix3d>(c.covariance).matrixL();
      whiten[j] = l.inverse();
      log_norm[j] = std::log(std::max(c.weight, 1e-300)) - std::log(l(0, 0) * l(1, 1) * l(2, 2)) -
                    1.5 * std::log(2 * std::numbers::pi);
    }
    double log_likelihood = 0;
    for (size_t i = 0; i < n; ++i) {
      double best = -std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < k; ++j) {
        log_p[j] = log_norm[j] - 0.5 * (whiten[j] * (points[i] - mixture.components[j].mean)).squaredNorm();
        best = std::max(best, log_p[j]);
      }
      std::vector<double>& r = mixture.responsibilities[i];
      double sum = 0;
      for (size_t j = 0; j < k; ++j) sum += r[j] = std::exp(log_p[j] - best);
      for (size_t j = 0; j < k; ++j) r[j] /= sum;
      log_likelihood += weights[i] * (best + std::log(sum));
    }
    // M step, each point weighted by its leaf's area; points in the outer loop, as stored.
    std::vector<double> mass(k, 0);
    std::vector<Eigen::Vector3d> means(k, Eigen::Vector3d::Zero());
    std::vector<Eigen::Matrix3d> covariances(k, Eigen::Matrix3d::Zero());
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < k; ++j) {
        const double w = weights[i] * mixture.responsibilities[i][j];
        mass[j] += w;
        means[j] += w * points[i];
      }
    for (size_t j = 0; j < k; ++j)
      if (mass[j] > 0) means[j] /= mass[j];
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < k; ++j) {
        const Eigen::Vector3d d = points[i] - means[j];
        covariances[j] += (weights[i] * mixture.responsibilities[i][j]) * d * d.transpose();
      }
    for (size_t j = 0; j < k; ++j) {
      GaussianComponent& c = mixture.components[j];
      if (mass[j] <= 1e-12 * total) {  // an empty component keeps its place and gets no weight
        c.weight = 0;
        continue;
      }
      c.mean = means[j];
      c.covariance = covariances[j] / mass[j] + floor * Eigen::Matrix3d::Identity();
      c.weight = mass[j] / total;
    }
    mixture.iterations = iteration + 1;
    mixture.log_likelihood = log_likelihood;
    if (std::abs(log_likelihood - previous) <= options.tolerance * std::abs(log_likelihood)) break;
    previous = log_likelihood;
  }
  return mixture;
}

std::vector<EllipsoidLevel> BuildEllipsoidHierarchy(const std::vector<Leaf>& leaves,
                                                    const std::vector<Eigen::Vector3f>& colours,
                                                    const EllipsoidClusterOptions& options) {
  options.Check();
  if (colours.size() != leaves.size()) Fail("ellipsoids: ", colours.size(), " colours for ", leaves.size(), " leaves");
  std::vector<EllipsoidLevel> levels;
  if (leaves.empty()) return levels;
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> areas;
  double mean_area = 0;
  for (const Leaf& leaf : leaves) {
    centres.push_back(leaf.centre.cast<double>());
    areas.push_back(std::max(leaf.area, 1e-12));
    mean_area += leaf.area / static_cast<double>(leaves.size());
  }
  // A leaf reaches about half its size past its centre.
  const double leaf_reach = 0.5 * std::sqrt(mean_area);
  const int finest = std::min<int>(options.max_clusters, static_cast<int>(leaves.size()));
  for (int clusters = 1;; clusters *= options.level_factor) {
    clusters = std::min(clusters, finest);
    const GaussianMixture mixture = FitGaussianMixture(centres, areas, clusters, options);
    EllipsoidLevel level;
    level.clusters = clusters;
    std::vector<double> sizes;
    for (size_t j = 0; j < mixture.components.size(); ++j) {
      // The weighted PCA of the centres with the fuzzy assignments (Clasen, fig. 5).
      double mass = 0;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero(), colour = Eigen::Vector3d::Zero();
      for (size_t i = 0; i < leaves.size(); ++i) {
        const double w = areas[i] * mixture.responsibilities[i][j];
        mass += w, mean += w * centres[i], colour += w * colours[i].cast<double>();
      }
      if (mass <= 0) continue;
      mean /= mass;
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for (size_t i = 0; i < leaves.size(); ++i) {
        const Eigen::Vector3d d = centres[i] - mean;
        covariance += areas[i] * mixture.responsibilities[i][j] * d * d.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(covariance / mass);
      Ellipsoid ellipsoid;
      ellipsoid.centre = mean.cast<float>();
      ellipsoid.colour = (colour / mass).cast<float>();
      Eigen::Vector3f radii;
      for (int a = 0; a < 3; ++a) {
        radii[a] = static_cast<float>(std::sqrt(5 * std::max(pca.eigenvalues()[a], 0.0)) + leaf_reach);
        ellipsoid.axes.col(a) = pca.eigenvectors().col(a).cast<float>() * radii[a];
      }
      level.ellipsoids.push_back(ellipsoid);
      sizes.push_back(EllipsoidArea(radii));
    }
    // Clasen: drop those under 1 % of the largest's surface (tiny, aliasing, hardly any shape).
    const double largest = sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end());
    std::vector<Ellipsoid> kept;
    for (size_t e = 0; e < level.ellipsoids.size(); ++e)
      if (sizes[e] >= options.min_area_fraction * largest) kept.push_back(level.ellipsoids[e]);
    level.ellipsoids = kept;
    levels.push_back(level);
    if (clusters >= finest) break;
  }
  return levels;
}

size_t EllipsoidLevelFor(const std::vector<EllipsoidLevel>& levels, double pixels_per_unit, double min_pixels) {
  size_t chosen = 0;
  for (size_t l = 0; l < levels.size(); ++l) {
    if (levels[l].ellipsoids.empty()) continue;
    double diameter = 0;
    for (const Ellipsoid& e : levels[l].ellipsoids)
      diameter += 2 * std::cbrt(std::abs(static_cast<double>(e.axes.determinant()))) * pixels_per_unit;
    diameter /= static_cast<double>(levels[l].ellipsoids.size());
    if (diameter >= min_pixels) chosen = l;
  }
  return chosen;
}

std::vector<PointPrimitive> EllipsoidSurface(const std::vector<Ellipsoid>& ellipsoids, int segments) {
  std::vector<PointPrimitive> corners;
  const int rings = std::max(2, segments / 2);
  const auto unit = [&](int s, int r) {
    const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
    return Eigen::Vector3f(static_cast<float>(std::sin(theta) * std::cos(phi)),
                           static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
  };
  for (const Ellipsoid& e : ellipsoids) {
    // Normals transform by the inverse transpose of the stretch.
    const Eigen::Matrix3f normal_map = e.axes.inverse().transpose();
    const auto corner = [&](int s, int r) {
      const Eigen::Vector3f n = unit(s, r);
      return PointPrimitive{e.centre + e.axes * n, (normal_map * n).normalized(), e.colour};
    };
    for (int r = 0; r < rings; ++r)
      for (int s = 0; s < segments; ++s) {
        const PointPrimitive a = corner(s, r), b = corner(s + 1, r), c = corner(s + 1, r + 1), d = corner(s, r + 1);
        if (r > 0) corners.insert(corners.end(), {a, d, b});          // not at the top pole
        if (r < rings - 1) corners.insert(corners.end(), {b, d, c});  // not at the bottom pole
      }
  }
  return corners;
}

}  // namespace voltree
