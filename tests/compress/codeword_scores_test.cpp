// The matrix-product scores that shortlist nearest codewords: within their stated tolerance of
// the exact distances, for the AVX2 kernel and the portable one, even far from the origin.
#include "compress/codeword_scores.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "compress/vector_distance.h"

namespace voltree {
namespace {

TrainingSet Cloud(size_t count, int dimension, float offset, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0, 30);
  TrainingSet set;
  set.dimension = dimension;
  for (size_t i = 0; i < count * dimension; ++i) set.vectors.push_back(offset + normal(rng));
  return set;
}

void ExpectScoresWithinTolerance(int dimension, float offset, bool use_simd) {
  const TrainingSet set = Cloud(100, dimension, offset, 1);
  const TrainingSet words = Cloud(37, dimension, offset, 2);  // not a whole number of panels
  const Codebook codebook{dimension, std::vector<float>(words.vectors.begin(), words.vectors.end())};
  const CodewordScorer scorer(codebook, use_simd);
  const size_t padded = scorer.padded_size();
  ASSERT_EQ(padded % CodewordScorer::kPanel, 0u);
  std::vector<float> scores(CodewordScorer::kBlock * padded);
  float centred_norm2[CodewordScorer::kBlock], lowest[CodewordScorer::kBlock];
  std::vector<uint32_t> shortlist(padded);
  for (size_t first = 0; first < set.size(); first += CodewordScorer::kBlock) {
    const int rows = int(std::min<size_t>(CodewordScorer::kBlock, set.size() - first));
    scorer.Score(set.Vector(first), rows, scores.data(), centred_norm2, lowest);
    for (int r = 0; r < rows; ++r) {
      const float* row = scores.data() + r * padded;
      const float tolerance = scorer.Tolerance(centred_norm2[r]);
      uint32_t nearest = 0;
      float nearest_distance = INFINITY;
      for (uint32_t j = 0; j < codebook.size(); ++j) {
        const float exact = SquaredDistance(set.Vector(first + r), codebook.Codeword(j), nullptr, dimension);
        // Half the tolerance each way: it covers the best and the true nearest together.
        EXPECT_NEAR(centred_norm2[r] + row[j], exact, tolerance / 2) << "vector " << first + r << " codeword " << j;
        if (exact < nearest_distance) nearest_distance = exact, nearest = j;
      }
      for (size_t j = codebook.size(); j < padded; ++j) EXPECT_EQ(row[j], INFINITY);  // pads never win
      EXPECT_EQ(lowest[r], *std::min_element(row, row + codebook.size()));
      const size_t count = scorer.Shortlist(row, lowest[r] + tolerance, shortlist.data());
      EXPECT_TRUE(std::find(shortlist.begin(), shortlist.begin() + count, nearest) != shortlist.begin() + count);
    }
  }
}

TEST(CodewordScores, SimdKernelNearTheOrigin) { ExpectScoresWithinTolerance(48, 0, true); }
TEST(CodewordScores, SimdKernelFarFromTheOrigin) { ExpectScoresWithinTolerance(48, 5000, true); }
TEST(CodewordScores, PortableKernelFarFromTheOrigin) { ExpectScoresWithinTolerance(48, 5000, false); }
TEST(CodewordScores, OddDimensionBothKernels) {
  ExpectScoresWithinTolerance(13, 100, true);
  ExpectScoresWithinTolerance(13, 100, false);
}

}  // namespace
}  // namespace voltree
