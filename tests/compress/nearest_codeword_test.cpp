// The pruned nearest-codeword search returns exactly what brute force returns.
#include "compress/nearest_codeword.h"

#include <gtest/gtest.h>

#include <random>

namespace voltree {
namespace {

TrainingSet RandomSet(size_t count, int dimension, bool weighted, uint64_t seed, int levels = 0) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0, 20);
  TrainingSet set;
  set.dimension = dimension;
  // Clustered data like real textures; `levels` > 0 quantizes values to force exact ties.
  std::vector<float> centres(8 * dimension);
  for (float& c : centres) c = normal(rng) * 3;
  for (size_t i = 0; i < count; ++i) {
    const float* centre = centres.data() + (rng() % 8) * dimension;
    for (int d = 0; d < dimension; ++d) {
      float v = centre[d] + normal(rng);
      if (levels > 0) v = std::round(v / levels);
      set.vectors.push_back(v);
      if (weighted) set.weights.push_back(float(rng() % 5) / 4.f);
    }
  }
  return set;
}

Codebook FirstVectors(const TrainingSet& set, size_t count) {
  return {set.dimension, std::vector<float>(set.vectors.begin(), set.vectors.begin() + count * set.dimension)};
}

void ExpectSameAsBruteForce(const TrainingSet& set, const Codebook& codebook) {
  std::vector<uint32_t> assignment(set.size());
  for (size_t i = 0; i < set.size(); ++i) assignment[i] = uint32_t((i * 7919) % codebook.size());  // arbitrary hints
  std::vector<float> distances;
  AssignNearest(codebook, set, assignment, distances);
  for (size_t i = 0; i < set.size(); ++i) {
    const CodewordMatch expected = BruteForceNearest(codebook, set.Vector(i), set.Weights(i));
    ASSERT_EQ(assignment[i], expected.index) << "vector " << i;
    ASSERT_EQ(distances[i], expected.distance) << "vector " << i;
  }
}

TEST(NearestCodeword, PrunedSearchEqualsBruteForce) {
  const TrainingSet set = RandomSet(3000, 48, false, 1);
  ExpectSameAsBruteForce(set, FirstVectors(RandomSet(256, 48, false, 2), 256));
}

TEST(NearestCodeword, WeightedSearchEqualsBruteForce) {
  const TrainingSet set = RandomSet(3000, 48, true, 3);
  ExpectSameAsBruteForce(set, FirstVectors(RandomSet(256, 48, false, 4), 256));
}

TEST(NearestCodeword, TiesGoToTheLowestIndex) {
  // Coarsely quantized values and duplicated codewords make many exact ties.
  const TrainingSet set = RandomSet(2000, 16, false, 5, 40);
  Codebook codebook = FirstVectors(set, 64);
  codebook.codewords.insert(codebook.codewords.end(), codebook.codewords.begin(), codebook.codewords.end());
  ExpectSameAsBruteForce(set, codebook);
}

TEST(NearestCodeword, OddDimensionAndNoHints) {
  const TrainingSet set = RandomSet(500, 13, false, 6);
  const Codebook codebook = FirstVectors(RandomSet(40, 13, false, 7), 40);
  std::vector<uint32_t> assignment;  // no hints
  std::vector<float> distances;
  AssignNearest(codebook, set, assignment, distances);
  for (size_t i = 0; i < set.size(); ++i)
    ASSERT_EQ(assignment[i], BruteForceNearest(codebook, set.Vector(i), nullptr).index);
}

}  // namespace
}  // namespace voltree
