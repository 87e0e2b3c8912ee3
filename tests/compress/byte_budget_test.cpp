// The byte budget: the largest codebooks whose asset fits, found in few compressions.
#include "compress/byte_budget.h"

#include <gtest/gtest.h>

#include "compress/synthetic_volume.h"
#include "core/vtree.h"

namespace voltree {
namespace {

// 2476 billboards on 4 levels: small enough to compress in a tenth of a second.
Volume BudgetVolume() { return MakeSyntheticVolume({.billboards = 3000}); }

CompressOptions BudgetOptions(uint64_t max_bytes) {
  CompressOptions options;
  options.colour_codebook = options.alpha_codebook = 256;
  options.smallest_budget_codebook = 32;
  options.max_bytes = max_bytes;
  options.trade_codebooks = false;  // the equal sizes' ladder alone; the trade has its own test
  return options;
}

std::string SerializeRaw(VtreeAsset& asset) { return SerializeAsset(asset); }

// The asset at one pair of codebook sizes, compressed directly.
std::string BudgetBytesAt(const Volume& volume, int codebook) {
  CompressOptions options = BudgetOptions(0);
  options.colour_codebook = options.alpha_codebook = codebook;
  return SerializeAsset(CompressVolume(volume, options).asset);
}

TEST(ByteBudget, NoBudgetKeepsTheCodebooksAsGiven) {
  const Volume volume = BudgetVolume();
  const BudgetedCompression out = CompressWithinBudget(volume, BudgetOptions(0), SerializeRaw);
  EXPECT_TRUE(out.fits);
  EXPECT_EQ(out.attempts, 1);
  EXPECT_EQ(out.kept.colour_codebook, 256);
  EXPECT_TRUE(out.bytes == BudgetBytesAt(volume, 256));
}

TEST(ByteBudget, KeepsTheLargestCodebooksThatFit) {
  const Volume volume = BudgetVolume();
  const std::string at_256 = BudgetBytesAt(volume, 256), at_128 = BudgetBytesAt(volume, 128),
                    at_64 = BudgetBytesAt(volume, 64);
  ASSERT_GT(at_256.size(), at_128.size());  // the premise of the bisection, on this volume
  ASSERT_GT(at_128.size(), at_64.size());

  // A budget between the 128 and the 256 assets: 128 / 128, the same bytes as compressed directly.
  const BudgetedCompression between = CompressWithinBudget(volume, BudgetOptions(at_128.size() + 1), SerializeRaw);
  EXPECT_TRUE(between.fits);
  EXPECT_EQ(between.kept.colour_codebook, 128);
  EXPECT_EQ(between.kept.alpha_codebook, 128);
  EXPECT_TRUE(between.bytes == at_128);
  EXPECT_LE(between.attempts, 3);  // bisection over 256, 128, 64, 32, not one per rung
  // Exactly the size counts as within.
  EXPECT_EQ(CompressWithinBudget(volume, BudgetOptions(at_256.size()), SerializeRaw).kept.colour_codebook, 256);
  EXPECT_EQ(CompressWithinBudget(volume, BudgetOptions(at_256.size() - 1), SerializeRaw).kept.colour_codebook, 128);
  // The codebook sizes the asset records are those kept (eval --budget recompresses with them).
  EXPECT_EQ(ParseAsset(between.bytes, "budget").colour_codebook_size, 128u);
}

// The search starts where the index bits alone fit: the demo oak's 548 351 billboards in 1 MiB
// start at 128 / 128 (14 bits each, 960 KB), not at 512 / 512, which is 18 s of compression.
TEST(ByteBudget, StartsAtTheLargestRungWhoseIndexBitsFit) {
  const std::vector<std::pair<int, int>> ladder = {{2048, 2048}, {1024, 1024}, {512, 512},
                                                   {256, 256},   {128, 128},   {64, 64}};
  EXPECT_EQ(PredictedRung(ladder, 548351, 1 << 20), 4u);
  EXPECT_EQ(PredictedRung(ladder, 199000, 1 << 20), 0u);  // the sparse aspen: 2048 / 2048 at once
  EXPECT_EQ(PredictedRung(ladder, 548351, 0), 0u);        // no budget
  EXPECT_EQ(PredictedRung(ladder, 548351, 1000), 5u);     // nothing fits: the smallest
  // Exactly the index bits count as fitting: 1 000 billboards at 22 bits are 2 750 bytes.
  EXPECT_EQ(PredictedRung(ladder, 1000, 2750), 0u);
  EXPECT_EQ(PredictedRung(ladder, 1000, 2749), 1u);
}

TEST(ByteBudget, OverEvenAtTheSmallestSaysSo) {
  const Volume volume = BudgetVolume();
  const BudgetedCompression out = CompressWithinBudget(volume, BudgetOptions(1000), SerializeRaw);
  EXPECT_FALSE(out.fits);
  EXPECT_EQ(out.kept.colour_codebook, 32);
  EXPECT_EQ(out.kept.alpha_codebook, 32);
  EXPECT_TRUE(out.bytes == BudgetBytesAt(volume, 32));
  // A codebook already below the smallest the budget tries is left as given.
  CompressOptions small = BudgetOptions(1000);
  small.colour_codebook = 16;
  EXPECT_EQ(CompressWithinBudget(volume, small, SerializeRaw).kept.colour_codebook, 16);
}

// With the budget binding at equal sizes, colour codewords are traded for alpha ones only where
// the texture PSNR gains, the pair kept still fits, and it is exactly the asset compressed
// directly at those sizes (codebooks trained for one pair and reused in another are the same).
TEST(ByteBudget, TradesColourCodewordsForAlphaOnesWhereTheTexturePsnrGains) {
  // Leaves of two flat greens and many shapes, as on a dense crown: the alpha codewords matter.
  Volume volume = BudgetVolume();
  for (VolumeLevel& level : volume.levels)
    for (size_t texel = 0; texel * 4 < level.texels.size(); ++texel) {
      uint8_t* rgba = level.texels.data() + texel * 4;
      const bool dark = (texel / 16) % 2 == 1;  // per billboard of 4 x 4 texels
      const int green[3] = {dark ? 40 : 90, dark ? 90 : 160, dark ? 30 : 50};
      for (int c = 0; c < 3; ++c) rgba[c] = uint8_t(green[c] * rgba[3] / 255);
    }
  // A budget just over the 16 / 256 asset, under the 256 / 256 one: equal sizes keep 128 / 128.
  CompressOptions at_16_256 = BudgetOptions(0);
  at_16_256.colour_codebook = 16;
  at_16_256.alpha_codebook = 256;
  const CompressResult direct = CompressVolume(volume, at_16_256);
  VtreeAsset direct_asset = direct.asset;
  const std::string direct_bytes = SerializeAsset(direct_asset);
  const uint64_t budget = direct_bytes.size() + 1;
  ASSERT_GT(BudgetBytesAt(volume, 256).size(), budget);
  const BudgetedCompression equal = CompressWithinBudget(volume, BudgetOptions(budget), SerializeRaw);
  ASSERT_EQ(equal.kept.colour_codebook, 128);
  ASSERT_EQ(equal.kept.alpha_codebook, 128);
  CompressOptions trading = BudgetOptions(budget);
  trading.trade_codebooks = true;
  const BudgetedCompression traded = CompressWithinBudget(volume, trading, SerializeRaw);
  EXPECT_TRUE(traded.fits);
  EXPECT_EQ(traded.kept.colour_codebook, 16);
  EXPECT_EQ(traded.kept.alpha_codebook, 256);
  EXPECT_GT(traded.result.stats.psnr_dxt5, equal.result.stats.psnr_dxt5 + 1);  // 33.9 against 31.6 dB here
  EXPECT_TRUE(traded.bytes == direct_bytes);
  // Bisection over 128 ... 16 at 256 alpha codewords; 16 / 512 is known not to fit, so not tried.
  EXPECT_LE(traded.attempts, equal.attempts + 2);
  // The colour codebook may keep its size while the alpha one doubles: a budget just over the
  // 128 / 256 asset keeps that pair, not one with half the colour codewords.
  CompressOptions at_128_256 = BudgetOptions(0);
  at_128_256.colour_codebook = 128;
  VtreeAsset roomy_asset = CompressVolume(volume, at_128_256).asset;
  const std::string roomy_bytes = SerializeAsset(roomy_asset);
  ASSERT_GT(BudgetBytesAt(volume, 256).size(), roomy_bytes.size() + 1);
  CompressOptions roomy_budget = trading;
  roomy_budget.max_bytes = roomy_bytes.size() + 1;
  const BudgetedCompression roomy = CompressWithinBudget(volume, roomy_budget, SerializeRaw);
  EXPECT_EQ(roomy.kept.colour_codebook, 128);
  EXPECT_EQ(roomy.kept.alpha_codebook, 256);
  EXPECT_TRUE(roomy.bytes == roomy_bytes);
  // Where the alpha codewords gain nothing, the equal sizes stay: the flat greens made them gain.
  const BudgetedCompression leafy = CompressWithinBudget(BudgetVolume(), trading, SerializeRaw);
  EXPECT_EQ(leafy.kept.colour_codebook, leafy.kept.alpha_codebook);
}

}  // namespace
}  // namespace voltree
