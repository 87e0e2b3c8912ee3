// The matrix-product scores that shortlist nearest codewords: within their stated tolerance of
// the exact distances, plain and weighted, for the AVX2 kernel and the portable one, even far
// from the origin.
#include "compress/codeword_scores.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "compress/vector_distance.h"

namespace voltree {
namespace {

using Distance = CodewordScorer::Distance;

// Weights, when asked for, are texel alphas: in [0, 1], a quarter of them 0 (transparent texels).
TrainingSet Cloud(size_t count, int dimension, float offset, uint64_t seed, bool weighted = false) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0, 30);
  std::uniform_real_distribution<float> uniform(-0.33f, 1);
  TrainingSet set;
  set.dimension = dimension;
  for (size_t i = 0; i < count * dimension; ++i) {
    set.vectors.push_back(offset + normal(rng));
    if (weighted) set.weights.push_back(std::max(0.f, uniform(rng)));
  }
  return set;
}

void ExpectScoresWithinTolerance(int dimension, float offset, Distance distance, bool use_simd) {
  const bool weighted = distance == Distance::kWeighted;
  const TrainingSet set = Cloud(100, dimension, offset, 1, weighted);
  const TrainingSet words = Cloud(37, dimension, offset, 2);  // not a whole number of panels
  const Codebook codebook{dimension, std::vector<float>(words.vectors.begin(), words.vectors.end())};
  const CodewordScorer scorer(codebook, distance, use_simd);
  const size_t padded = scorer.padded_size();
  ASSERT_EQ(padded % CodewordScorer::kPanel, 0u);
  std::vector<float> scores(CodewordScorer::kBlock * padded);
  float tolerance[CodewordScorer::kBlock], lowest[CodewordScorer::kBlock];
  std::vector<uint32_t> shortlist(padded);
  for (size_t first = 0; first < set.size(); first += CodewordScorer::kBlock) {
    const int rows = int(std::min<size_t>(CodewordScorer::kBlock, set.size() - first));
    scorer.Score(set.Vector(first), set.Weights(first), rows, scores.data(), lowest, tolerance);
    for (int r = 0; r < rows; ++r) {
      const float* row = scores.data() + r * padded;
      const float* vector = set.Vector(first + r);
      const float* weights = set.Weights(first + r);
      std::vector<double> exact(codebook.size());
      for (uint32_t j = 0; j < codebook.size(); ++j)
        exact[j] = SquaredDistance(vector, codebook.Codeword(j), weights, dimension);
      const uint32_t nearest = std::min_element(exact.begin(), exact.end()) - exact.begin();
      // A score is the exact distance less a constant of the row, within half the tolerance, so
      // the differences between scores are the differences between distances within all of it.
      for (uint32_t j = 0; j < codebook.size(); ++j) {
        EXPECT_NEAR(double(row[j]) - row[nearest], exact[j] - exact[nearest], tolerance[r])
            << "vector " << first + r << " codeword " << j;
      }
      for (size_t j = codebook.size(); j < padded; ++j) EXPECT_EQ(row[j], INFINITY);  // pads never win
      EXPECT_EQ(lowest[r], *std::min_element(row, row + codebook.size()));
      const size_t count = scorer.Shortlist(row, lowest[r] + tolerance[r], shortlist.data());
      EXPECT_TRUE(std::find(shortlist.begin(), shortlist.begin() + count, nearest) != shortlist.begin() + count);
      EXPECT_LT(count, codebook.size() / 2) << "a tolerance this loose shortlists most of the codebook";
    }
  }
}

TEST(CodewordScores, SimdKernelNearTheOrigin) { ExpectScoresWithinTolerance(48, 0, Distance::kPlain, true); }
TEST(CodewordScores, SimdKernelFarFromTheOrigin) { ExpectScoresWithinTolerance(48, 5000, Distance::kPlain, true); }
TEST(CodewordScores, PortableKernelFarFromTheOrigin) { ExpectScoresWithinTolerance(48, 5000, Distance::kPlain, false); }
TEST(CodewordScores, OddDimensionBothKernels) {
  ExpectScoresWithinTolerance(13, 100, Distance::kPlain, true);
  ExpectScoresWithinTolerance(13, 100, Distance::kPlain, false);
}
TEST(CodewordScores, WeightedBothKernels) {
  for (const bool use_simd : {true, false}) {
    ExpectScoresWithinTolerance(48, 5000, Distance::kWeighted, use_simd);
    ExpectScoresWithinTolerance(16, 100, Distance::kWeighted, use_simd);
    ExpectScoresWithinTolerance(13, 0, Distance::kWeighted, use_simd);
  }
}

}  // namespace
}  // namespace voltree
