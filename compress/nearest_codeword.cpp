#include "compress/nearest_codeword.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <memory>

#include "compress/codeword_scores.h"
#include "compress/vector_distance.h"

namespace voltree {
namespace {

// Keeps the best match with brute force's tie rule: smaller distance, then smaller index.
void Consider(CodewordMatch& best, uint32_t index, float distance) {
  if (distance < best.distance || (distance == best.distance && index < best.index)) {
    best = {index, distance};
  }
}

// The weighted scan: the hint (the vector's previous codeword) first, so that partial distance
// elimination cuts the others short from the start.
CodewordMatch WeightedNearest(const Codebook& codebook, const float* vector, const float* weights, uint32_t hint) {
  const int dimension = codebook.dimension;
  const uint32_t count = static_cast<uint32_t>(codebook.size());
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  if (hint < count) best = {hint, SquaredDistance(vector, codebook.Codeword(hint), weights, dimension)};
  for (uint32_t i = 0; i < count; ++i) {
    if (i == hint) continue;
    Consider(best, i, SquaredDistance(vector, codebook.Codeword(i), weights, dimension, best.distance));
  }
  return best;
}

// Plain L2: the scorer shortlists, SquaredDistance decides, so the result is brute force's.
void AssignByScores(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                    std::vector<float>& distances) {
  constexpr int kBlock = CodewordScorer::kBlock;
  const CodewordScorer scorer(codebook);
  const size_t padded = scorer.padded_size();
  const int dimension = set.dimension;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, set.size(), 512), [&](const tbb::blocked_range<size_t>& range) {
    // Scratch left uninitialized: Score writes every value before it is read.
    const std::unique_ptr<float[]> scores(new float[kBlock * padded]);
    const std::unique_ptr<uint32_t[]> shortlist(new uint32_t[padded]);
    float lowest[kBlock], centred_norm2[kBlock];
    for (size_t first = range.begin(); first < range.end(); first += kBlock) {
      const int rows = static_cast<int>(std::min<size_t>(kBlock, range.end() - first));
      scorer.Score(set.Vector(first), rows, scores.get(), centred_norm2, lowest);
      for (int r = 0; r < rows; ++r) {
        const float* row = scores.get() + r * padded;
        const float* vector = set.Vector(first + r);
        const float limit = lowest[r] + scorer.Tolerance(centred_norm2[r]);
        CodewordMatch best{0, std::numeric_limits<float>::infinity()};
        const size_t count = scorer.Shortlist(row, limit, shortlist.get());
        for (size_t m = 0; m < count; ++m) {
          const uint32_t j = shortlist[m];
          Consider(best, j, SquaredDistance(vector, codebook.Codeword(j), nullptr, dimension, best.distance));
        }
        assignment[first + r] = best.index;
        distances[first + r] = best.distance;
      }
    }
  });
}

}  // namespace

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
  if (!set.weighted()) return AssignByScores(codebook, set, assignment, distances);
  // Each vector's result depends only on its inputs, so the schedule cannot change the output.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const CodewordMatch match = WeightedNearest(codebook, set.Vector(i), set.Weights(i), assignment[i]);
      assignment[i] = match.index;
      distances[i] = match.distance;
    }
  });
}

}  // namespace voltree
