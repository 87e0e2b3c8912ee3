// The whole compress stage on a synthetic volume: quality, determinism, records.
#include "compress/compress_volume.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>

#include "compress/billboard_vectors.h"
#include "compress/synthetic_volume.h"
#include "core/error.h"
#include "needs_two_cores.h"

namespace voltree {
namespace {

Volume TestVolume() {
  SyntheticVolumeOptions options;
  options.billboards = 3000;
  return MakeSyntheticVolume(options);
}

CompressOptions SmallCodebooks() {
  CompressOptions options;
  options.colour_codebook = 128;
  options.alpha_codebook = 128;
  return options;
}

TEST(CompressVolume, QualityAndRecords) {
  const Volume volume = TestVolume();
  const CompressResult result = CompressVolume(volume, SmallCodebooks());
  const VtreeAsset& asset = result.asset;
  ASSERT_EQ(asset.levels.size(), volume.levels.size());
  EXPECT_EQ(asset.BillboardCount(), result.stats.billboards);
  EXPECT_EQ(asset.colour_codebook_size, 128u);
  for (size_t l = 0; l < volume.levels.size(); ++l)
    for (size_t b = 0; b < volume.levels[l].billboards.size(); ++b) {
      EXPECT_EQ(asset.levels[l].billboards[b].cell, volume.levels[l].billboards[b].cell);
      EXPECT_EQ(asset.levels[l].billboards[b].view, volume.levels[l].billboards[b].view);
    }
  // Measured on this volume (2476 billboards, 128 + 128 codewords): 29.1 dB after VQ, 29.0 dB
  // after DXT5 (32 codewords: 25.8 dB, 512: 33.0 dB).
  EXPECT_GT(result.stats.psnr_vq, 28.0);
  EXPECT_GT(result.stats.psnr_dxt5, 27.5);
  EXPECT_LE(result.stats.psnr_dxt5, result.stats.psnr_vq + 0.5);
  EXPECT_EQ(asset.atlas.tile_count, 128u);
  EXPECT_EQ(asset.atlas.width, 48u);  // 12 tiles of 4 texels per row
}

TEST(CompressVolume, MoreCodewordsMoreQuality) {
  const Volume volume = TestVolume();
  CompressOptions options = SmallCodebooks();
  options.colour_codebook = options.alpha_codebook = 32;
  const double small = CompressVolume(volume, options).stats.psnr_vq;
  options.colour_codebook = options.alpha_codebook = 512;
  const double large = CompressVolume(volume, options).stats.psnr_vq;
  EXPECT_GT(large, small + 2.0);
}

TEST(CompressVolume, Deterministic) {
  const Volume volume = TestVolume();
  CompressOptions options = SmallCodebooks();
  options.alpha_weighted = true;
  EXPECT_EQ(SerializeAsset(CompressVolume(volume, options).asset),
            SerializeAsset(CompressVolume(volume, options).asset));
}

TEST(CompressVolume, SameBytesWhateverTheThreads) {
  VOLTREE_SKIP_UNLESS_TWO_CORES();
  const Volume volume = TestVolume();
  for (bool weighted : {false, true}) {
    CompressOptions options = SmallCodebooks();
    options.alpha_weighted = weighted;
    const std::string threaded = SerializeAsset(CompressVolume(volume, options).asset);
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(SerializeAsset(CompressVolume(volume, options).asset), threaded) << (weighted ? "weighted" : "plain");
  }
}

// Each codebook keeps its own codeword rule: the modified one's codewords are training vectors,
// the classic one's are means that no training vector equals; the asset records both.
TEST(CompressVolume, EachCodebookFollowsItsOwnRule) {
  const Volume volume = TestVolume();
  const std::vector<uint8_t> texels = GatherTexels(volume);
  const int texel_count = volume.texels * volume.texels;
  const auto members = [](const TrainingSet& set, const Codebook& codebook) {
    size_t found = 0;
    for (size_t k = 0; k < codebook.size(); ++k)
      for (size_t i = 0; i < set.size(); ++i)
        if (std::equal(set.Vector(i), set.Vector(i) + set.dimension, codebook.Codeword(k))) {
          ++found;
          break;
        }
    return found;
  };
  for (const bool colour_classic : {true, false}) {
    CompressOptions options = SmallCodebooks();
    options.colour_rule = colour_classic ? CodewordRule::kCentroid : CodewordRule::kClosestMember;
    options.alpha_rule = colour_classic ? CodewordRule::kClosestMember : CodewordRule::kCentroid;
    const CompressResult result = CompressVolume(volume, options);
    const TrainingSet colours = ColourVectors(texels, texel_count, options.space, options.alpha_weighted);
    const TrainingSet alphas = AlphaVectors(texels, texel_count);
    const Codebook &colour = result.stats.colour.codebook, &alpha = result.stats.alpha.codebook;
    // A cluster of one member is its own mean, so the classic codebook may hold a few members.
    EXPECT_EQ(members(colours, colour) == colour.size(), !colour_classic);
    EXPECT_EQ(members(alphas, alpha) == alpha.size(), colour_classic);
    const nlohmann::json& recorded = result.asset.provenance.at("options");
    EXPECT_EQ(recorded.at("gla"), colour_classic ? "classic" : "modified");
    EXPECT_EQ(recorded.at("alpha_gla"), colour_classic ? "modified" : "classic");
  }
}

// The provenance's options read back as written; an older asset's single "gla" serves both
// codebooks; a rule that is neither is refused, naming the field.
TEST(CompressOptions, ReadBackFromTheProvenance) {
  CompressOptions written = SmallCodebooks();
  written.space = ColourSpace::kRgb;
  written.colour_rule = CodewordRule::kClosestMember;
  written.alpha_rule = CodewordRule::kCentroid;
  written.alpha_weighted = false;
  written.tolerance = 0.01;
  written.max_iterations = 7;
  written.seed = 9;
  written.black_threshold = 2;
  const CompressOptions read = CompressOptions::FromJson(written.ToJson(), CompressOptions{});
  EXPECT_EQ(read.ToJson(), written.ToJson());

  CompressOptions absent;
  absent.colour_codebook = 77;
  const CompressOptions old = CompressOptions::FromJson({{"gla", "classic"}}, absent);
  EXPECT_EQ(old.colour_codebook, 77);
  EXPECT_EQ(old.colour_rule, CodewordRule::kCentroid);
  EXPECT_EQ(old.alpha_rule, CodewordRule::kCentroid);
  try {
    CompressOptions::FromJson({{"alpha_gla", "median"}}, absent);
    ADD_FAILURE() << "an unknown rule was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("options.alpha_gla"), std::string::npos) << error.what();
  }
}

TEST(CompressVolume, RejectsEmptyVolumesAndBadOptions) {
  Volume empty;
  empty.levels.resize(1);
  EXPECT_THROW(CompressVolume(empty, SmallCodebooks()), Error);
  CompressOptions bad;
  bad.alpha_codebook = 70000;
  EXPECT_THROW(bad.Check(), Error);
}

}  // namespace
}  // namespace voltree
