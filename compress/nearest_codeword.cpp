#include "compress/nearest_codeword.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
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

CodewordMatch NearestCodewordSearch::Find(const float* vector, const float* weights, uint32_t hint,
                                          float* second) const {
  if (weights) return FindWeighted(vector, weights, hint);
  const int dimension = codebook_.dimension;
  const size_t count = codebook_.size();
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  CodewordMatch best{0, kInfinity};
  // With `second`, the search is for the two nearest: runner_up is the second smallest distance
  // seen (a lower bound, for partial distances), and the search only stops where it is exceeded.
  float runner_up = kInfinity;
  auto consider = [&](uint32_t index) {
    const float limit = second ? runner_up : best.distance;
    const float distance = SquaredDistance(vector, codebook_.Codeword(index), nullptr, dimension, limit);
    const CodewordMatch before = best;
    Consider(best, index, distance);
    runner_up = std::min(runner_up, best.index == index && best.distance == distance ? before.distance : distance);
  };
  if (hint < count) best = {hint, SquaredDistance(vector, codebook_.Codeword(hint), nullptr, dimension)};
  const float norm = Norm(vector, dimension);
  // Scan outward from the codewords whose norm is closest to |x|; a direction closes when the
  // norm gap alone exceeds the distance sought, and that gap bounds everything beyond it.
  const size_t start = std::lower_bound(sorted_norms_.begin(), sorted_norms_.end(), norm) - sorted_norms_.begin();
  size_t up = start;      // next candidate above
  size_t down = start;    // one past the next candidate below
  bool up_open = up < count, down_open = down > 0;
  while (up_open || down_open) {
    const float sought = second ? runner_up : best.distance;
    if (up_open) {
      const float gap = sorted_norms_[up] - norm;
      if (NormBoundExceeds(gap, sought)) {
        up_open = false;
        runner_up = std::min(runner_up, gap * gap);
      } else {
        const uint32_t index = by_norm_[up];
        if (index != best.index || best.distance == kInfinity) consider(index);
        up_open = ++up < count;
      }
    }
    if (down_open) {
      const float gap = norm - sorted_norms_[down - 1];
      if (NormBoundExceeds(gap, sought)) {
        down_open = false;
        runner_up = std::min(runner_up, gap * gap);
      } else {
        const uint32_t index = by_norm_[down - 1];
        if (index != best.index || best.distance == kInfinity) consider(index);
        down_open = --down > 0;
      }
    }
  }
  if (second) *second = runner_up;
  return best;
}

CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights) {
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  for (uint32_t i = 0; i < codebook.size(); ++i)
    Consider(best, i, SquaredDistance(vector, codebook.Codeword(i), weights, codebook.dimension));
  return best;
}

namespace {

// How far each codeword moved since `before` (not squared), rounded up so the bounds stay safe.
std::vector<float> CodewordMoves(const Codebook& before, const Codebook& after) {
  std::vector<float> moves(after.size());
  for (size_t k = 0; k < after.size(); ++k)
    moves[k] = std::sqrt(SquaredDistance(before.Codeword(k), after.Codeword(k), nullptr, after.dimension)) *
                   (1.f + 1e-5f) + 1e-6f;
  return moves;
}

}  // namespace

size_t AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                     std::vector<float>& distances, AssignmentBounds* bounds) {
  const size_t count = set.size();
  if (set.weighted()) bounds = nullptr;
  // Bounds from an earlier call are usable when they describe these vectors and codewords.
  const bool carried = bounds && assignment.size() == count && bounds->upper.size() == count &&
                       bounds->codebook.dimension == codebook.dimension && bounds->codebook.size() == codebook.size();
  if (assignment.size() != count) assignment.assign(count, UINT32_MAX);
  distances.resize(count);
  // The few codewords that moved most (a re-seeded cell jumps across the space) are measured
  // exactly; the lower bounds only pay for the largest move among the rest.
  std::vector<uint32_t> jumpers;
  float rest_move = 0;
  if (carried) {
    const std::vector<float> moves = CodewordMoves(bounds->codebook, codebook);
    std::vector<uint32_t> order(moves.size());
    std::iota(order.begin(), order.end(), 0u);
    const size_t exact = std::min<size_t>(8, order.size());
    std::partial_sort(order.begin(), order.begin() + exact, order.end(),
                      [&](uint32_t a, uint32_t b) { return moves[a] > moves[b] || (moves[a] == moves[b] && a < b); });
    jumpers.assign(order.begin(), order.begin() + exact);
    for (size_t k = exact; k < order.size(); ++k) rest_move = std::max(rest_move, moves[order[k]]);
  }
  if (bounds) bounds->upper.resize(count), bounds->lower.resize(count);
  const NearestCodewordSearch search(codebook);
  std::atomic<size_t> searched = 0;
  // Each vector's result depends only on its inputs, so the schedule cannot change the output.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const float* x = set.Vector(i);
      if (carried) {
        // Hamerly's test: the old codeword is still strictly the nearest, so the search would
        // return it. The margin covers float rounding of the bounds.
        const uint32_t a = assignment[i];
        const float d = SquaredDistance(x, codebook.Codeword(a), nullptr, set.dimension);
        const float upper = std::sqrt(d);
        const float needed = upper * (1.f + 1e-4f) + 1e-6f;  // what the lower bound must exceed
        float lower = bounds->lower[i] - rest_move;
        for (uint32_t j : jumpers) {
          if (j == a || lower <= needed) continue;
          // A partial distance is a lower bound too, and enough once it exceeds `needed`.
          const float bound = (lower * 1.0001f) * (lower * 1.0001f);
          lower = std::min(lower, std::sqrt(SquaredDistance(x, codebook.Codeword(j), nullptr, set.dimension, bound)));
        }
        if (needed < lower) {
          distances[i] = d;
          bounds->upper[i] = upper;
          bounds->lower[i] = lower;
          continue;
        }
      }
      searched.fetch_add(1, std::memory_order_relaxed);
      float runner_up = 0;
      const CodewordMatch match = search.Find(x, set.Weights(i), assignment[i], bounds ? &runner_up : nullptr);
      assignment[i] = match.index;
      distances[i] = match.distance;
      if (bounds) bounds->upper[i] = std::sqrt(match.distance), bounds->lower[i] = std::sqrt(runner_up);
    }
  });
  if (bounds) bounds->codebook = codebook;
  return searched;
}

}  // namespace voltree
