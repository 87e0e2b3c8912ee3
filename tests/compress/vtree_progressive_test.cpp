// Progressive .vtree: the atlas before the levels, levels coarse to fine, so that the first bytes
// of a file draw its coarsest levels; a partial read says what is missing; max_level stops early.
#include <gtest/gtest.h>

#include "compress/compress_volume.h"
#include "compress/synthetic_volume.h"
#include "core/error.h"
#include "core/vtree.h"

namespace voltree {
namespace {

const VtreeAsset& FourLevelAsset() {
  static const VtreeAsset asset = [] {
    SyntheticVolumeOptions volume;
    volume.billboards = 600;
    volume.levels = 4;
    CompressOptions options;
    options.colour_codebook = 40;
    options.alpha_codebook = 24;
    return CompressVolume(MakeSyntheticVolume(volume), options).asset;
  }();
  return asset;
}

// Where each level's BBRD chunk ends: the bytes from which that level can be drawn.
std::vector<size_t> LevelEnds(const std::string& bytes) {
  std::vector<size_t> ends;
  for (const auto& chunk : ListChunks(bytes, "tree.vtree"))
    if (chunk.tag == "BBRD") ends.push_back(chunk.offset + chunk.stored_bytes);
  return ends;
}

TEST(VtreeProgressive, AtlasComesBeforeTheLevels) {
  const auto chunks = ListChunks(SerializeAsset(FourLevelAsset()), "tree.vtree");
  ASSERT_GE(chunks.size(), 4u);
  EXPECT_EQ(chunks[0].tag, "HEAD");
  EXPECT_EQ(chunks[1].tag, "ATLS");
  for (size_t i = 2; i < chunks.size(); ++i) EXPECT_EQ(chunks[i].tag, i % 2 == 0 ? "CELL" : "BBRD");
}

TEST(VtreeProgressive, APrefixDrawsItsWholeLevelsAndNamesWhatIsMissing) {
  for (bool zstd : {false, true}) {
    VtreeWriteOptions write;
    write.zstd = zstd;
    const std::string bytes = SerializeAsset(FourLevelAsset(), write);
    const std::vector<size_t> ends = LevelEnds(bytes);
    const size_t levels = FourLevelAsset().levels.size();
    ASSERT_EQ(ends.size(), levels);
    for (size_t k = 0; k + 1 < levels; ++k) {
      // Cut exactly after level k, a few bytes into level k + 1's CELL, and inside its BBRD.
      for (size_t cut : {ends[k], ends[k] + 5, ends[k] + 40, ends[k + 1] - 1}) {
        const std::string_view prefix = std::string_view(bytes).substr(0, cut);
        EXPECT_THROW(ParseAsset(prefix, "tree.vtree"), Error) << "a plain read accepts a cut at " << cut;
        VtreeLoadReport report;
        VtreeReadOptions read;
        read.allow_partial = true;
        read.report = &report;
        const VtreeAsset partial = ParseAsset(prefix, "tree.vtree", read);
        ASSERT_EQ(partial.levels.size(), k + 1) << "cut at " << cut;
        for (size_t l = 0; l <= k; ++l) EXPECT_EQ(partial.levels[l].cells, FourLevelAsset().levels[l].cells);
        EXPECT_EQ(partial.atlas.dxt5, FourLevelAsset().atlas.dxt5);
        EXPECT_TRUE(report.truncated);
        EXPECT_EQ(report.levels_loaded, k + 1);
        EXPECT_EQ(report.levels_in_file, levels);
        EXPECT_EQ(report.missing.rfind("levels " + std::to_string(k + 1) + ".." + std::to_string(levels - 1) +
                                           " of 0.." + std::to_string(levels - 1) +
                                           " are missing: the file ends at byte " + std::to_string(cut),
                                       0),
                  0u)
            << report.missing;
      }
    }
    // Before level 0 is whole there is nothing to draw: an error, partial or not.
    VtreeReadOptions read;
    read.allow_partial = true;
    EXPECT_THROW(ParseAsset(std::string_view(bytes).substr(0, ends[0] - 1), "tree.vtree", read), Error);
    // The whole file is not partial.
    VtreeLoadReport report;
    read.report = &report;
    EXPECT_EQ(ParseAsset(bytes, "tree.vtree", read).levels.size(), levels);
    EXPECT_FALSE(report.truncated);
    EXPECT_EQ(report.missing, "");
  }
}

TEST(VtreeProgressive, ListChunksMarksTheChunkTheFileEndsIn) {
  const std::string bytes = SerializeAsset(FourLevelAsset());
  const size_t cut = LevelEnds(bytes)[1] + 100;
  EXPECT_THROW(ListChunks(std::string_view(bytes).substr(0, cut), "tree.vtree"), Error);
  const auto chunks = ListChunks(std::string_view(bytes).substr(0, cut), "tree.vtree", /*allow_partial=*/true);
  ASSERT_FALSE(chunks.empty());
  EXPECT_FALSE(chunks.back().complete);
  EXPECT_EQ(chunks.back().offset, LevelEnds(bytes)[1]);
  EXPECT_EQ(chunks.back().tag, "CELL");
  for (size_t i = 0; i + 1 < chunks.size(); ++i) EXPECT_TRUE(chunks[i].complete);
}

TEST(VtreeProgressive, MaxLevelLoadsTheCoarserLevelsOnly) {
  const std::string bytes = SerializeAsset(FourLevelAsset());
  const size_t levels = FourLevelAsset().levels.size();
  for (int max_level : {0, 1, int(levels) - 1, int(levels) + 3}) {
    VtreeLoadReport report;
    VtreeReadOptions read;
    read.max_level = max_level;
    read.report = &report;
    const VtreeAsset asset = ParseAsset(bytes, "tree.vtree", read);
    EXPECT_EQ(asset.levels.size(), std::min<size_t>(max_level + 1, levels));
    EXPECT_EQ(report.levels_in_file, levels);
    // Only what it loads has to be there.
    const VtreeAsset prefix =
        ParseAsset(std::string_view(bytes).substr(0, LevelEnds(bytes)[asset.levels.size() - 1]), "tree.vtree", read);
    EXPECT_EQ(prefix.levels.size(), asset.levels.size());
  }
  VtreeReadOptions bad;
  bad.max_level = -2;
  try {
    ParseAsset(bytes, "tree.vtree", bad);
    ADD_FAILURE() << "max_level -2 accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("VtreeReadOptions.max_level"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace voltree
