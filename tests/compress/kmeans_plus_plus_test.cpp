// k-means++ seeding: one centre per well-separated cluster, plain and weighted, and determinism.
#include "compress/kmeans_plus_plus.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace voltree {
namespace {

// `clusters` tight blobs (spread 1) far apart (about 1000), `per_cluster` vectors each, shuffled.
TrainingSet Blobs(int clusters, int per_cluster, int dimension, bool weighted, std::vector<int>* label) {
  std::mt19937_64 rng(3);
  std::normal_distribution<float> normal(0, 1);
  std::vector<float> centres(clusters * dimension);
  for (float& c : centres) c = 1000 * normal(rng);
  std::vector<int> order(clusters * per_cluster);
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i) % clusters;
  std::shuffle(order.begin(), order.end(), rng);
  TrainingSet set;
  set.dimension = dimension;
  for (int cluster : order) {
    for (int d = 0; d < dimension; ++d) {
      set.vectors.push_back(centres[cluster * dimension + d] + normal(rng));
      if (weighted) set.weights.push_back(1.f);
    }
    label->push_back(cluster);
  }
  return set;
}

// The blob a seeded centre was copied from.
int BlobOf(const TrainingSet& set, const std::vector<int>& label, const float* centre) {
  for (size_t i = 0; i < set.size(); ++i)
    if (std::equal(centre, centre + set.dimension, set.Vector(i))) return label[i];
  ADD_FAILURE() << "a centre that is not a training vector";
  return -1;
}

class KMeansPlusPlus : public ::testing::TestWithParam<bool> {};

TEST_P(KMeansPlusPlus, PutsOneCentreInEveryBlob) {
  // The potential of a blob without a centre dwarfs everything else, so each new centre must land
  // in an empty blob; a seeding that failed to update the distances would pile them up.
  std::vector<int> label;
  const TrainingSet set = Blobs(24, 40, 12, GetParam(), &label);
  const Codebook codebook = SeedKMeansPlusPlus(set, 24, 7);
  ASSERT_EQ(codebook.size(), 24u);
  std::set<int> blobs;
  for (size_t k = 0; k < codebook.size(); ++k) blobs.insert(BlobOf(set, label, codebook.Codeword(k)));
  EXPECT_EQ(blobs.size(), 24u);
}

TEST_P(KMeansPlusPlus, SameSeedSameCentres) {
  std::vector<int> label;
  const TrainingSet set = Blobs(8, 200, 16, GetParam(), &label);
  EXPECT_EQ(SeedKMeansPlusPlus(set, 100, 5).codewords, SeedKMeansPlusPlus(set, 100, 5).codewords);
  EXPECT_NE(SeedKMeansPlusPlus(set, 100, 5).codewords, SeedKMeansPlusPlus(set, 100, 6).codewords);
}

INSTANTIATE_TEST_SUITE_P(PlainAndWeighted, KMeansPlusPlus, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Weighted" : "Plain"; });

TEST(KMeansPlusPlusCounts, NeverMoreCentresThanVectors) {
  std::vector<int> label;
  const TrainingSet set = Blobs(2, 3, 4, false, &label);
  EXPECT_EQ(SeedKMeansPlusPlus(set, 50, 1).size(), 6u);
}

}  // namespace
}  // namespace voltree
