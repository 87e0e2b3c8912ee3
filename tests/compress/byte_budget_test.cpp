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
  EXPECT_LE(traded.attempts, equal.attempts + 2);  // bisection over 64, 32, 16
  // Where the alpha codewords gain nothing, the equal sizes stay: the flat greens made them gain.
  const BudgetedCompression leafy = CompressWithinBudget(BudgetVolume(), trading, SerializeRaw);
  EXPECT_EQ(leafy.kept.colour_codebook, leafy.kept.alpha_codebook);
}

}  // namespace
}  // namespace voltree
