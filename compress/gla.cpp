#include "compress/gla.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "compress/nearest_codeword.h"
#include "compress/vector_distance.h"
#include "core/error.h"

namespace voltree {
namespace {

// Uniform double in [0, 1) from 53 random bits: unlike std::uniform_real_distribution this is
// the same on every standard library.
double UniformUnit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

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
int ReseedEmptyCells(const TrainingSet& set, const Clusters& clusters, std::vector<float> distances,
                     Codebook& codebook) {
  const size_t count = codebook.size();
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
    const float d = SquaredDistance(set.Vector(members[m]), centre, set.Weights(members[m]), set.dimension,
                                    best_distance);
    if (d < best_distance) best_distance = d, best = members[m];
  }
  return best;
}

}  // namespace

CodewordRule ParseCodewordRule(const std::string& name) {
  if (name == "classic") return CodewordRule::kCentroid;
  if (name == "modified") return CodewordRule::kClosestMember;
  Fail("--gla: expected 'classic' or 'modified', got '", name, "'");
}

std::string CodewordRuleName(CodewordRule rule) {
  return rule == CodewordRule::kCentroid ? "classic" : "modified";
}

void GlaOptions::Check() const {
  if (codebook_size < 1 || codebook_size > 65536)
    Fail("codebook size: expected 1..65536, got ", codebook_size);
  if (!(tolerance >= 0 && tolerance < 1)) Fail("GLA tolerance: expected [0, 1), got ", tolerance);
  if (max_iterations < 1) Fail("GLA iterations: expected >= 1, got ", max_iterations);
  if (seeding_trials < 1 || seeding_trials > 64) Fail("k-means++ trials: expected 1..64, got ", seeding_trials);
}

void ClusterMean(const TrainingSet& set, const uint32_t* members, size_t count, float* mean) {
  const int dimension = set.dimension;
  std::vector<double> sum(dimension, 0), weight(dimension, 0), plain(dimension, 0);
  for (size_t m = 0; m < count; ++m) {
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

Codebook SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials) {
  const size_t n = set.size();
  count = std::min(count, n);
  trials = std::max(trials, 1);
  Codebook codebook{set.dimension, std::vector<float>(count * set.dimension)};
  if (count == 0) return codebook;
  std::mt19937_64 rng(seed);
  std::vector<float> nearest(n, std::numeric_limits<float>::infinity());
  std::vector<uint32_t> owner(n, 0);  // index of the nearest centre so far
  std::vector<std::vector<float>> candidate_nearest(trials, std::vector<float>(n));
  std::vector<std::vector<uint32_t>> candidate_owner(trials, std::vector<uint32_t>(n));
  std::vector<float> centre_gap;  // squared distance from the candidate to every chosen centre
  // nearest/owner updated with a candidate centre (the k-th), into `out`/`out_owner`. For plain L2,
  // |c - a| >= 2 |x - a| (a = x's nearest centre) proves c cannot be nearer, so x is skipped
  // without computing its distance; otherwise partial distance elimination bounds the work.
  auto update = [&](const float* centre, size_t k, std::vector<float>& out, std::vector<uint32_t>& out_owner) {
    centre_gap.resize(k);
    for (size_t j = 0; j < k; ++j) centre_gap[j] = SquaredDistance(centre, codebook.Codeword(j), nullptr, set.dimension);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        out[i] = nearest[i];
        out_owner[i] = owner[i];
        if (!set.weighted() && k > 0 && centre_gap[owner[i]] >= 4.f * nearest[i]) continue;
        const float d = SquaredDistance(set.Vector(i), centre, set.Weights(i), set.dimension, nearest[i]);
        if (d < nearest[i]) out[i] = d, out_owner[i] = uint32_t(k);
      }
    });
  };
  auto sample = [&](double total) {  // index with probability nearest[i] / total
    const double target = UniformUnit(rng) * total;
    double running = 0;
    for (size_t i = 0; i < n; ++i) {
      running += nearest[i];
      if (running > target && nearest[i] > 0) return i;
    }
    for (size_t i = n; i-- > 0;)
      if (nearest[i] > 0) return i;
    return n - 1;
  };
  size_t chosen = rng() % n;
  for (size_t k = 0; k < count; ++k) {
    if (k > 0) {
      const double total = SumInOrder(nearest);
      if (total <= 0) {  // fewer distinct vectors than codewords: duplicates are harmless
        chosen = (chosen + 1) % n;
      } else {
        double best_potential = std::numeric_limits<double>::infinity();
        size_t best = 0;
        for (int t = 0; t < trials; ++t) {
          const size_t candidate = sample(total);
          update(set.Vector(candidate), k, candidate_nearest[t], candidate_owner[t]);
          const double potential = SumInOrder(candidate_nearest[t]);
          if (potential < best_potential) best_potential = potential, best = size_t(t), chosen = candidate;
        }
        nearest.swap(candidate_nearest[best]);
        owner.swap(candidate_owner[best]);
      }
    }
    std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(k));
    if (k == 0 || nearest[chosen] != 0) {  // first centre, or the duplicate branch above
      update(codebook.Codeword(k), k, candidate_nearest[0], candidate_owner[0]);
      nearest.swap(candidate_nearest[0]);
      owner.swap(candidate_owner[0]);
    }
  }
  return codebook;
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
  return RunGlaFrom(set, options,
                    SeedKMeansPlusPlus(set, static_cast<size_t>(options.codebook_size), options.seed,
                                       options.seeding_trials),
                    observer);
}

GlaResult RunGlaFrom(const TrainingSet& set, const GlaOptions& options, Codebook initial, const GlaObserver& observer) {
  options.Check();
  if (set.size() == 0) Fail("GLA: no training vectors");
  if (initial.dimension != set.dimension || initial.size() == 0)
    Fail("GLA: initial codebook of dimension ", initial.dimension, " for vectors of dimension ", set.dimension);
  const size_t n = set.size();
  GlaResult result;
  result.codebook = std::move(initial);
  const size_t k_count = result.codebook.size();
  std::vector<float> distances;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    AssignNearest(result.codebook, set, result.assignment, distances);
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

}  // namespace voltree
