#include "compress/nearest_codeword.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "compress/vector_distance.h"

namespace voltree {
namespace {

float Norm(const float* v, int dimension) {
  double sum = 0;
  for (int i = 0; i < dimension; ++i) sum += double(v[i]) * v[i];
  return static_cast<float>(std::sqrt(sum));
}

// Keeps the best match with brute force's tie rule: smaller distance, then smaller index.
void Consider(CodewordMatch& best, uint32_t index, float distance) {
  if (distance < best.distance || (distance == best.distance && index < best.index)) {
    best = {index, distance};
  }
}

// The norm bound is exact in real arithmetic; the margin covers float rounding of the norms so
// that a codeword at exactly the best distance is never skipped.
bool NormBoundExceeds(float norm_gap, float best) {
  return norm_gap * norm_gap > best * (1.f + 1e-4f) + 1e-6f;
}

}  // namespace

NearestCodewordSearch::NearestCodewordSearch(const Codebook& codebook) : codebook_(codebook) {
  const size_t count = codebook.size();
  std::vector<float> norms(count);
  for (size_t i = 0; i < count; ++i) norms[i] = Norm(codebook.Codeword(i), codebook.dimension);
  by_norm_.resize(count);
  std::iota(by_norm_.begin(), by_norm_.end(), 0u);
  std::sort(by_norm_.begin(), by_norm_.end(), [&](uint32_t a, uint32_t b) {
    return norms[a] < norms[b] || (norms[a] == norms[b] && a < b);
  });
  sorted_norms_.resize(count);
  for (size_t i = 0; i < count; ++i) sorted_norms_[i] = norms[by_norm_[i]];
}

CodewordMatch NearestCodewordSearch::FindWeighted(const float* vector, const float* weights,
                                                  uint32_t hint) const {
  const int dimension = codebook_.dimension;
  const uint32_t count = static_cast<uint32_t>(codebook_.size());
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  if (hint < count) best = {hint, SquaredDistance(vector, codebook_.Codeword(hint), weights, dimension)};
  for (uint32_t i = 0; i < count; ++i) {
    if (i == hint) continue;
    Consider(best, i, SquaredDistance(vector, codebook_.Codeword(i), weights, dimension, best.distance));
  }
  return best;
}

CodewordMatch NearestCodewordSearch::Find(const float* vector, const float* weights, uint32_t hint) const {
  if (weights) return FindWeighted(vector, weights, hint);
  const int dimension = codebook_.dimension;
  const size_t count = codebook_.size();
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  if (hint < count) best = {hint, SquaredDistance(vector, codebook_.Codeword(hint), nullptr, dimension)};
  const float norm = Norm(vector, dimension);
  // Scan outward from the codewords whose norm is closest to |x|.
  const size_t start = std::lower_bound(sorted_norms_.begin(), sorted_norms_.end(), norm) - sorted_norms_.begin();
  size_t up = start;      // next candidate above
  size_t down = start;    // one past the next candidate below
  bool up_open = up < count, down_open = down > 0;
  while (up_open || down_open) {
    if (up_open) {
      if (NormBoundExceeds(sorted_norms_[up] - norm, best.distance)) {
        up_open = false;
      } else {
        const uint32_t index = by_norm_[up];
        if (index != best.index || best.distance == std::numeric_limits<float>::infinity())
          Consider(best, index, SquaredDistance(vector, codebook_.Codeword(index), nullptr, dimension, best.distance));
        up_open = ++up < count;
      }
    }
    if (down_open) {
      if (NormBoundExceeds(norm - sorted_norms_[down - 1], best.distance)) {
        down_open = false;
      } else {
        const uint32_t index = by_norm_[down - 1];
        if (index != best.index || best.distance == std::numeric_limits<float>::infinity())
          Consider(best, index, SquaredDistance(vector, codebook_.Codeword(index), nullptr, dimension, best.distance));
        down_open = --down > 0;
      }
    }
  }
  return best;
}

CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights) {
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  for (uint32_t i = 0; i < codebook.size(); ++i)
    Consider(best, i, SquaredDistance(vector, codebook.Codeword(i), weights, codebook.dimension));
  return best;
}

void AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances) {
  const size_t count = set.size();
  if (assignment.size() != count) assignment.assign(count, UINT32_MAX);
  distances.resize(count);
  const NearestCodewordSearch search(codebook);
  // Each vector's result depends only on its inputs, so the schedule cannot change the output.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const CodewordMatch match = search.Find(set.Vector(i), set.Weights(i), assignment[i]);
      assignment[i] = match.index;
      distances[i] = match.distance;
    }
  });
}

}  // namespace voltree
