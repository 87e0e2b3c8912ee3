#include "compress/kmeans_plus_plus.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "compress/vector_distance.h"

namespace voltree {
namespace {

// Uniform double in [0, 1) from 53 random bits: unlike std::uniform_real_distribution this is
// the same on every standard library.
double UniformUnit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

}  // namespace

Codebook SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials) {
  const size_t n = set.size();
  count = std::min(count, n);
  trials = std::max(trials, 1);
  Codebook codebook{set.dimension, std::vector<float>(count * set.dimension)};
  if (count == 0) return codebook;
  // The potential (sum of squared distances to the nearest centre) is kept per fixed chunk of
  // vectors and added in chunk order: the same whatever the threads, and sampling walks the
  // chunk sums before scanning one chunk.
  constexpr size_t kChunk = 4096;
  const size_t chunks = (n + kChunk - 1) / kChunk;
  std::mt19937_64 rng(seed);
  std::vector<float> nearest(n, std::numeric_limits<float>::infinity());
  std::vector<uint32_t> owner(n, 0);  // index of the nearest centre so far
  std::vector<double> chunk_sum(chunks, 0);
  std::vector<float> centre_gap;      // squared distance from the candidate to every chosen centre
  auto total = [](const std::vector<double>& sums) { return std::accumulate(sums.begin(), sums.end(), 0.0); };
  // The squared distance of vector i to its nearest centre once `centre` (the k-th) is added. For
  // plain L2, |c - a| >= 2 |x - a| (a = x's nearest centre) proves c cannot be nearer, so x is
  // skipped without measuring it; otherwise partial distance elimination bounds the work.
  auto with_centre = [&](size_t i, const float* centre, size_t k) {
    const float before = nearest[i];
    if (!set.weighted() && k > 0 && centre_gap[owner[i]] >= 4.f * before) return before;
    return std::min(before, SquaredDistance(set.Vector(i), centre, set.Weights(i), set.dimension, before));
  };
  auto measure_gaps = [&](const float* centre, size_t k) {
    centre_gap.resize(k);
    for (size_t j = 0; j < k; ++j) centre_gap[j] = SquaredDistance(centre, codebook.Codeword(j), nullptr, set.dimension);
  };
  // A candidate's potential per chunk, read-only, so the trials need no copies of the state.
  auto evaluate = [&](const float* centre, size_t k, std::vector<double>& sums) {
    measure_gaps(centre, k);
    sums.resize(chunks);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
      double sum = 0;
      for (size_t i = c * kChunk, end = std::min(n, i + kChunk); i != end; ++i) sum += with_centre(i, centre, k);
      sums[c] = sum;
    });
  };
  auto add = [&](const float* centre, size_t k) {
    measure_gaps(centre, k);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
      double sum = 0;
      for (size_t i = c * kChunk, end = std::min(n, i + kChunk); i != end; ++i) {
        const float d = with_centre(i, centre, k);
        if (d < nearest[i]) nearest[i] = d, owner[i] = uint32_t(k);
        sum += nearest[i];
      }
      chunk_sum[c] = sum;
    });
  };
  auto sample = [&](double potential) {  // index with probability nearest[i] / potential
    const double target = UniformUnit(rng) * potential;
    double running = 0;
    size_t c = 0;
    while (c + 1 < chunks && running + chunk_sum[c] <= target) running += chunk_sum[c++];
    for (size_t i = c * kChunk; i < n; ++i) {
      running += nearest[i];
      if (running > target && nearest[i] > 0) return i;
    }
    for (size_t i = n; i-- > 0;)
      if (nearest[i] > 0) return i;
    return n - 1;
  };
  size_t chosen = rng() % n;
  std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(0));
  add(codebook.Codeword(0), 0);
  std::vector<size_t> candidates(trials);
  std::vector<std::vector<double>> trial_sums(trials);
  for (size_t k = 1; k < count; ++k) {
    const double potential = total(chunk_sum);
    if (potential <= 0) {  // fewer distinct vectors than codewords: duplicates are harmless
      chosen = (chosen + 1) % n;
    } else {
      double best_potential = std::numeric_limits<double>::infinity();
      for (int t = 0; t < trials; ++t) {
        candidates[t] = sample(potential);
        evaluate(set.Vector(candidates[t]), k, trial_sums[t]);
        const double with = total(trial_sums[t]);
        if (with < best_potential) best_potential = with, chosen = candidates[t];
      }
    }
    std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(k));
    add(codebook.Codeword(k), k);
  }
  return codebook;
}

}  // namespace voltree
