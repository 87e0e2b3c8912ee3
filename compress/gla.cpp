#include "compress/gla.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "compress/nearest_codeword.h"
#include "compress/vector_distance.h"
#include "core/error.h"

namespace voltree {
namespace {

double SumInOrder(const std::vector<float>& values) {
  double sum = 0;
  for (float v : values) sum += v;
  return sum;
}

// Members of every cluster in ascending vector order (a counting sort, so deterministic).
struct Clusters {
  std::vector<uint32_t> offsets;  // cluster k: members[offsets[k], offsets[k + 1])
  std::vector<uint32_t> members;

  Clusters(const std::vector<uint32_t>& assignment, size_t cluster_count)
      : offsets(cluster_count + 1, 0), members(assignment.size()) {
    for (uint32_t k : assignment) ++offsets[k + 1];
    for (size_t k = 0; k < cluster_count; ++k) offsets[k + 1] += offsets[k];
    std::vector<uint32_t> cursor(offsets.begin(), offsets.end() - 1);
    for (uint32_t i = 0; i < assignment.size(); ++i) members[cursor[assignment[i]]++] = i;
  }
  size_t Size(size_t k) const { return offsets[k + 1] - offsets[k]; }
  const uint32_t* Begin(size_t k) const { return members.data() + offsets[k]; }
};

// Moves every empty cell's codeword onto the member of the currently worst cell (largest total
// distortion) that is farthest from its codeword, so the next assignment splits that cell.
int ReseedEmptyCells(const TrainingSet& set, const Clusters& clusters, const std::vector<float>& measured,
                     Codebook& codebook) {
  const size_t count = codebook.size();
  bool any_empty = false;
  for (size_t k = 0; k < count && !any_empty; ++k) any_empty = clusters.Size(k) == 0;
  if (!any_empty) return 0;
  std::vector<float> distances = measured;  // taken vectors are zeroed below
  std::vector<double> cell_distortion(count, 0);
  for (size_t k = 0; k < count; ++k)
    for (size_t m = 0; m < clusters.Size(k); ++m) cell_distortion[k] += distances[clusters.Begin(k)[m]];
  int reseeded = 0;
  for (size_t k = 0; k < count; ++k) {
    if (clusters.Size(k) != 0) continue;
    const size_t worst = std::max_element(cell_distortion.begin(), cell_distortion.end()) - cell_distortion.begin();
    if (cell_distortion[worst] <= 0) break;  // every vector already sits on a codeword
    uint32_t farthest = clusters.Begin(worst)[0];
    for (size_t m = 0; m < clusters.Size(worst); ++m) {
      const uint32_t i = clusters.Begin(worst)[m];
      if (distances[i] > distances[farthest]) farthest = i;
    }
    std::copy_n(set.Vector(farthest), set.dimension, codebook.Codeword(k));
    cell_distortion[worst] -= distances[farthest];
    distances[farthest] = 0;  // taken: the next empty cell picks another vector
    ++reseeded;
  }
  return reseeded;
}

// Index of the member closest to `centre` (lowest index on ties).
uint32_t ClosestMember(const TrainingSet& set, const uint32_t* members, size_t count, const float* centre) {
  uint32_t best = members[0];
  float best_distance = std::numeric_limits<float>::infinity();
  for (size_t m = 0; m < count; ++m) {
    const float d =
        SquaredDistance(set.Vector(members[m]), centre, set.Weights(members[m]), set.dimension, best_distance);
    if (d < best_distance) best_distance = d, best = members[m];
  }
  return best;
}

// Lloyd iterations from `initial`; `assignment` and `distances` are the first assignment when
// given (from the seeding), else it is computed.
GlaResult RunLloyd(const TrainingSet& set, const GlaOptions& options, Codebook initial,
                   std::vector<uint32_t> assignment, std::vector<float> distances, const GlaObserver& observer) {
  const size_t n = set.size();
  GlaResult result;
  result.codebook = std::move(initial);
  result.assignment = std::move(assignment);
  const size_t k_count = result.codebook.size();
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    if (iteration > 0 || distances.size() != n) AssignNearest(result.codebook, set, result.assignment, distances);
    const double distortion = SumInOrder(distances) / double(n);
    result.distortion_history.push_back(distortion);
    result.iterations = iteration + 1;
    if (observer) observer(iteration, distortion);
    if (iteration > 0) {
      const double previous = result.distortion_history[iteration - 1];
      if (distortion <= 0 || (previous - distortion) / previous < options.tolerance) break;
    }
    if (iteration + 1 == options.max_iterations) break;  // keep the codebook that made this assignment
    // Lloyd update: each codeword moves to the mean of its cell.
    const Clusters clusters(result.assignment, k_count);
    tbb::parallel_for(size_t(0), k_count, [&](size_t k) {
      if (clusters.Size(k) > 0) ClusterMean(set, clusters.Begin(k), clusters.Size(k), result.codebook.Codeword(k));
    });
    result.reseeded += ReseedEmptyCells(set, clusters, distances, result.codebook);
  }
  result.distortion = result.distortion_history.back();
  if (options.rule == CodewordRule::kClosestMember) {
    const Clusters clusters(result.assignment, k_count);
    tbb::parallel_for(size_t(0), k_count, [&](size_t k) {
      if (clusters.Size(k) == 0) return;
      std::vector<float> mean(set.dimension);
      ClusterMean(set, clusters.Begin(k), clusters.Size(k), mean.data());
      const uint32_t member = ClosestMember(set, clusters.Begin(k), clusters.Size(k), mean.data());
      std::copy_n(set.Vector(member), set.dimension, result.codebook.Codeword(k));
    });
    AssignNearest(result.codebook, set, result.assignment, distances);
    result.distortion = SumInOrder(distances) / double(n);
  }
  return result;
}

}  // namespace

CodewordRule ParseCodewordRule(const std::string& name) {
  if (name == "classic") return CodewordRule::kCentroid;
  if (name == "modified") return CodewordRule::kClosestMember;
  Fail("unknown codeword rule '", name, "'; expected classic or modified");
}

std::string CodewordRuleName(CodewordRule rule) { return rule == CodewordRule::kCentroid ? "classic" : "modified"; }

void GlaOptions::Check() const {
  if (codebook_size < 1 || codebook_size > 65536)
    FailOption("GlaOptions.codebook_size", "must be in 1..65536, got ", codebook_size);
  if (!(tolerance >= 0 && tolerance < 1)) FailOption("GlaOptions.tolerance", "must be in [0, 1), got ", tolerance);
  if (max_iterations < 1) FailOption("GlaOptions.max_iterations", "must be at least 1, got ", max_iterations);
  if (seeding_trials < 1 || seeding_trials > 64)
    FailOption("GlaOptions.seeding_trials", "must be in 1..64, got ", seeding_trials);
}

void ClusterMean(const TrainingSet& set, const uint32_t* members, size_t count, float* mean) {
  const int dimension = set.dimension;
  std::vector<double> sum(dimension, 0), weight(dimension, 0), plain(dimension, 0);
  constexpr size_t kAhead = 8;  // members are scattered over the set: fetch ahead
  for (size_t m = 0; m < count; ++m) {
    if (m + kAhead < count) PrefetchVector(set.Vector(members[m + kAhead]), dimension);
    const float* x = set.Vector(members[m]);
    const float* w = set.Weights(members[m]);
    for (int i = 0; i < dimension; ++i) {
      plain[i] += x[i];
      if (w) sum[i] += double(w[i]) * x[i], weight[i] += w[i];
    }
  }
  for (int i = 0; i < dimension; ++i) {
    // A component no member cares about (all weights 0) takes the plain mean.
    mean[i] = static_cast<float>(weight[i] > 0 ? sum[i] / weight[i] : plain[i] / double(count));
  }
}

double MeanDistortion(const Codebook& codebook, const TrainingSet& set) {
  std::vector<uint32_t> assignment;
  std::vector<float> distances;
  AssignNearest(codebook, set, assignment, distances);
  return set.size() ? SumInOrder(distances) / double(set.size()) : 0;
}

GlaResult RunGla(const TrainingSet& set, const GlaOptions& options, const GlaObserver& observer) {
  options.Check();
  set.Check();
  if (set.size() == 0) Fail("GLA: no training vectors");
  Seeds seeds =
      SeedKMeansPlusPlus(set, static_cast<size_t>(options.codebook_size), options.seed, options.seeding_trials);
  // The seeding leaves every vector with its nearest centre: the first assignment, already made.
  return RunLloyd(set, options, std::move(seeds.centres), std::move(seeds.nearest), std::move(seeds.distances),
                  observer);
}

GlaResult RunGlaFrom(const TrainingSet& set, const GlaOptions& options, Codebook initial, const GlaObserver& observer) {
  options.Check();
  if (set.size() == 0) Fail("GLA: no training vectors");
  if (initial.dimension != set.dimension || initial.size() == 0)
    Fail("GLA: initial codebook of dimension ", initial.dimension, " for vectors of dimension ", set.dimension);
  return RunLloyd(set, options, std::move(initial), {}, {}, observer);
}

}  // namespace voltree
