// k-means++ seeding: one centre per well-separated cluster, plain and weighted, determinism, and
// the nearest centres it reports are exactly what a brute-force search finds (the bounds it
// prunes with never drop a vector that should have moved).
#include "compress/kmeans_plus_plus.h"

#include "compress/nearest_codeword.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>
#include <set>

#include "needs_two_cores.h"

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

TEST_P(KMeansPlusPlus, PutsOneCenterInEveryBlob) {
  // The potential of a blob without a centre dwarfs everything else, so each new centre must land
  // in an empty blob; a seeding that failed to update the distances would pile them up.
  std::vector<int> label;
  const TrainingSet set = Blobs(24, 40, 12, GetParam(), &label);
  const Codebook codebook = SeedKMeansPlusPlus(set, 24, 7).centres;
  ASSERT_EQ(codebook.size(), 24u);
  std::set<int> blobs;
  for (size_t k = 0; k < codebook.size(); ++k) blobs.insert(BlobOf(set, label, codebook.Codeword(k)));
  EXPECT_EQ(blobs.size(), 24u);
}

TEST_P(KMeansPlusPlus, SameSeedSameCenters) {
  std::vector<int> label;
  const TrainingSet set = Blobs(8, 200, 16, GetParam(), &label);
  EXPECT_EQ(SeedKMeansPlusPlus(set, 100, 5).centres.codewords, SeedKMeansPlusPlus(set, 100, 5).centres.codewords);
  EXPECT_NE(SeedKMeansPlusPlus(set, 100, 5).centres.codewords, SeedKMeansPlusPlus(set, 100, 6).centres.codewords);
}

// Texture-like vectors: 16 "texels" sharing a patch colour plus noise, so the components are
// correlated as in real billboards and the principal-axes sketch has something to find.
TrainingSet Patches(size_t count, bool weighted, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0, 1);
  TrainingSet set;
  set.dimension = 48;
  for (size_t i = 0; i < count; ++i) {
    const float patch[3] = {50 + 20 * normal(rng), 10 * normal(rng), 30 + 10 * normal(rng)};
    const float gradient = 3 * normal(rng);
    for (int texel = 0; texel < 16; ++texel)
      for (int channel = 0; channel < 3; ++channel) {
        set.vectors.push_back(patch[channel] + gradient * float(texel % 4) + 2 * normal(rng));
        if (weighted) set.weights.push_back(float(rng() % 4) / 3.f);
      }
  }
  return set;
}

TEST_P(KMeansPlusPlus, ReportsExactlyTheNearestCenters) {
  const TrainingSet set = Patches(4000, GetParam(), 11);
  for (bool use_simd : {true, false}) {
    const Seeds seeds = SeedKMeansPlusPlus(set, 96, 3, 3, use_simd);
    std::vector<uint32_t> nearest;
    std::vector<float> distances;
    AssignNearest(seeds.centres, set, nearest, distances);
    ASSERT_EQ(seeds.nearest.size(), set.size());
    for (size_t i = 0; i < set.size(); ++i) {
      ASSERT_EQ(seeds.nearest[i], nearest[i]) << "vector " << i << (use_simd ? " (SIMD)" : " (baseline)");
      ASSERT_EQ(seeds.distances[i], distances[i]) << "vector " << i;
    }
  }
}

TEST(KMeansPlusPlusCounts, SameSeedsWhateverTheThreads) {
  VOLTREE_SKIP_UNLESS_TWO_CORES();
  const TrainingSet set = Patches(3000, false, 12);
  const Seeds threaded = SeedKMeansPlusPlus(set, 64, 5);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const Seeds single = SeedKMeansPlusPlus(set, 64, 5);
  EXPECT_EQ(single.centres.codewords, threaded.centres.codewords);
  EXPECT_EQ(single.nearest, threaded.nearest);
}

TEST(KMeansPlusPlusCounts, DuplicatesKeepTheLowestCenter) {
  // Two distinct vectors, each many times: once both are centres the rest are duplicates.
  TrainingSet set;
  set.dimension = 4;
  for (int i = 0; i < 40; ++i) set.vectors.insert(set.vectors.end(), {float(i % 2), 1, 2, 3});
  const Seeds seeds = SeedKMeansPlusPlus(set, 5, 9);
  std::vector<uint32_t> nearest;
  std::vector<float> distances;
  AssignNearest(seeds.centres, set, nearest, distances);
  EXPECT_EQ(seeds.nearest, nearest);
  EXPECT_EQ(seeds.distances, distances);
}

INSTANTIATE_TEST_SUITE_P(PlainAndWeighted, KMeansPlusPlus, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Weighted" : "Plain"; });

TEST(KMeansPlusPlusCounts, NeverMoreCentersThanVectors) {
  std::vector<int> label;
  const TrainingSet set = Blobs(2, 3, 4, false, &label);
  EXPECT_EQ(SeedKMeansPlusPlus(set, 50, 1).centres.size(), 6u);
}

}  // namespace
}  // namespace voltree
