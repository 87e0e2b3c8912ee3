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

}  // namespace

CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights) {
  CodewordMatch best{0, std::numeric_limits<float>::infinity()};
  for (uint32_t i = 0; i < codebook.size(); ++i)
    Consider(best, i, SquaredDistance(vector, codebook.Codeword(i), weights, codebook.dimension));
  return best;
}

// The scorer shortlists, SquaredDistance decides, so the result is brute force's. Each vector's
// result depends only on its inputs, so the schedule cannot change the output.
void AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances) {
  constexpr int kBlock = CodewordScorer::kBlock;
  assignment.resize(set.size());
  distances.resize(set.size());
  const CodewordScorer scorer(codebook,
                              set.weighted() ? CodewordScorer::Distance::kWeighted : CodewordScorer::Distance::kPlain);
  const size_t padded = scorer.padded_size();
  const int dimension = set.dimension;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, set.size(), 512), [&](const tbb::blocked_range<size_t>& range) {
    // Scratch left uninitialized: Score writes every value before it is read.
    const std::unique_ptr<float[]> scores(new float[kBlock * padded]);
    const std::unique_ptr<uint32_t[]> shortlist(new uint32_t[padded]);
    float lowest[kBlock], tolerance[kBlock];
    for (size_t first = range.begin(); first < range.end(); first += kBlock) {
      const int rows = static_cast<int>(std::min<size_t>(kBlock, range.end() - first));
      scorer.Score(set.Vector(first), set.Weights(first), rows, scores.get(), lowest, tolerance);
      for (int r = 0; r < rows; ++r) {
        const float* row = scores.get() + r * padded;
        const float* vector = set.Vector(first + r);
        const float* weights = set.Weights(first + r);
        CodewordMatch best{0, std::numeric_limits<float>::infinity()};
        const size_t count = scorer.Shortlist(row, lowest[r] + tolerance[r], shortlist.get());
        for (size_t m = 0; m < count; ++m) {
          const uint32_t j = shortlist[m];
          Consider(best, j, SquaredDistance(vector, codebook.Codeword(j), weights, dimension, best.distance));
        }
        assignment[first + r] = best.index;
        distances[first + r] = best.distance;
      }
    }
  });
}

}  // namespace voltree
