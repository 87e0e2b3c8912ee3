#include "compress/kmeans_plus_plus.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "compress/vector_distance.h"

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

}  // namespace

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

}  // namespace voltree
