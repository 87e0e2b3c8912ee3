// GLA: monotone distortion, modified-GLA codewords are training vectors, degenerate sizes.
#include "compress/gla.h"

#include <gtest/gtest.h>

#include <random>

#include "compress/billboard_vectors.h"
#include "compress/synthetic_volume.h"
#include "compress/vector_distance.h"
#include "core/error.h"

namespace voltree {
namespace {

TrainingSet LeafColours(bool weighted, int billboards = 3000) {
  SyntheticVolumeOptions options;
  options.billboards = billboards;
  const Volume volume = MakeSyntheticVolume(options);
  return ColourVectors(GatherTexels(volume), 16, ColourSpace::kLab, weighted);
}

void ExpectMonotone(const GlaResult& result) {
  ASSERT_GE(result.distortion_history.size(), 2u);
  for (size_t i = 1; i < result.distortion_history.size(); ++i) {
    // Float rounding of the centroids may add ~1e-7 relative; measured drops are >= 1e-3 until the end.
    EXPECT_LE(result.distortion_history[i], result.distortion_history[i - 1] * (1 + 1e-6)) << "iteration " << i;
  }
}

TEST(Gla, DistortionNeverIncreases) {
  GlaOptions options;
  options.codebook_size = 64;
  options.rule = CodewordRule::kCentroid;
  options.tolerance = 0;  // run every iteration
  options.max_iterations = 15;
  const GlaResult result = RunGla(LeafColours(false), options);
  EXPECT_EQ(result.iterations, 15);
  ExpectMonotone(result);
  EXPECT_LT(result.distortion_history.back(), 0.9 * result.distortion_history.front());
}

TEST(Gla, WeightedDistortionNeverIncreases) {
  GlaOptions options;
  options.codebook_size = 64;
  options.rule = CodewordRule::kCentroid;
  options.tolerance = 0;
  options.max_iterations = 15;
  ExpectMonotone(RunGla(LeafColours(true), options));
}

TEST(Gla, ModifiedCodewordsAreTrainingVectors) {
  const TrainingSet set = LeafColours(false);
  GlaOptions options;
  options.codebook_size = 100;
  options.rule = CodewordRule::kClosestMember;
  const GlaResult result = RunGla(set, options);
  ASSERT_EQ(result.codebook.size(), 100u);
  for (size_t k = 0; k < result.codebook.size(); ++k) {
    bool found = false;
    for (size_t i = 0; i < set.size() && !found; ++i)
      found = std::equal(set.Vector(i), set.Vector(i) + set.dimension, result.codebook.Codeword(k));
    EXPECT_TRUE(found) << "codeword " << k << " is not a training vector";
  }
}

TEST(Gla, SizeOneGivesMeanOrMedoid) {
  const TrainingSet set = LeafColours(false, 500);
  GlaOptions options;
  options.codebook_size = 1;
  options.rule = CodewordRule::kCentroid;
  const GlaResult classic = RunGla(set, options);
  std::vector<double> mean(set.dimension, 0);
  for (size_t i = 0; i < set.size(); ++i)
    for (int d = 0; d < set.dimension; ++d) mean[d] += set.Vector(i)[d];
  for (int d = 0; d < set.dimension; ++d) EXPECT_NEAR(classic.codebook.codewords[d], mean[d] / set.size(), 1e-3);

  options.rule = CodewordRule::kClosestMember;
  const GlaResult modified = RunGla(set, options);
  std::vector<float> mean_f(mean.begin(), mean.end());
  for (float& m : mean_f) m /= float(set.size());
  size_t closest = 0;
  float best = std::numeric_limits<float>::infinity();
  for (size_t i = 0; i < set.size(); ++i) {
    const float d = SquaredDistance(set.Vector(i), mean_f.data(), nullptr, set.dimension);
    if (d < best) best = d, closest = i;
  }
  EXPECT_TRUE(
      std::equal(set.Vector(closest), set.Vector(closest) + set.dimension, modified.codebook.codewords.begin()));
}

TEST(Gla, MoreCodewordsThanVectorsIsExact) {
  TrainingSet set;
  set.dimension = 4;
  set.vectors = {0, 0, 0, 0, 1, 2, 3, 4, 1, 2, 3, 4, 9, 9, 9, 9};  // 3 distinct of 4
  GlaOptions options;
  options.codebook_size = 10;
  const GlaResult result = RunGla(set, options);
  EXPECT_EQ(result.codebook.size(), 4u);  // clamped to the number of vectors
  EXPECT_EQ(result.distortion, 0);
}

TEST(Gla, EmptyCellsAreReseeded) {
  // Codeword 100 attracts no vector: it must move onto the farthest member of the worst cell.
  TrainingSet set;
  set.dimension = 1;
  set.vectors = {0, 1, 0, 1, 10, 11, 10, 11};
  GlaOptions options;
  options.rule = CodewordRule::kCentroid;
  options.tolerance = 0;
  options.max_iterations = 5;
  const GlaResult result = RunGlaFrom(set, options, Codebook{1, {0.5f, 10.5f, 100.f}});
  EXPECT_GE(result.reseeded, 1);
  EXPECT_LT(result.distortion, result.distortion_history.front());
  for (float c : result.codebook.codewords) EXPECT_LE(c, 11.f);
}

TEST(Gla, SameSeedSameCodebook) {
  const TrainingSet set = LeafColours(true, 2000);
  GlaOptions options;
  options.codebook_size = 50;
  const GlaResult a = RunGla(set, options), b = RunGla(set, options);
  EXPECT_EQ(a.codebook.codewords, b.codebook.codewords);
  EXPECT_EQ(a.assignment, b.assignment);
  options.seed = 2;
  EXPECT_NE(RunGla(set, options).codebook.codewords, a.codebook.codewords);
}

TEST(Gla, RejectsBadOptions) {
  GlaOptions options;
  options.codebook_size = 0;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_THROW(ParseCodewordRule("median"), Error);
}

}  // namespace
}  // namespace voltree
