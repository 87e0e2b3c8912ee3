// voltree info: where each level of a progressive .vtree becomes drawable, and what a truncated
// file still holds (its whole levels, the chunk it ends in, the levels missing).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/files.h"
#include "core/vtree.h"
#include "pipeline/voltree_binary.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

// Three levels, two views, every cell of a diagonal seen from both.
VtreeAsset ThreeLevels() {
  VtreeAsset asset;
  asset.views = {{"a.png", {5, 0, 0}, {-1, 0, 0}, {0, 0, 1}}, {"b.png", {0, 5, 0}, {0, -1, 0}, {0, 0, 1}}};
  asset.colour_codebook_size = asset.alpha_codebook_size = 2;
  asset.atlas = {8, 4, 4, 2, 2, std::vector<uint8_t>(32, 0x11)};
  for (uint16_t l = 0; l < 3; ++l) {
    VtreeLevel level;
    level.resolution = 1u << l;
    for (uint16_t i = 0; i < level.resolution; ++i) level.cells.push_back({i, i, i});
    level.density.assign(level.cells.size(), 1.0f);
    for (uint32_t c = 0; c < level.cells.size(); ++c)
      for (uint16_t v = 0; v < 2; ++v) level.billboards.push_back({c, v, uint16_t(c % 2), v});
    level.billboards_before_pruning = level.billboards.size();
    asset.levels.push_back(level);
  }
  return asset;
}

TEST(InfoCli, PrintsWhereEachLevelIsDrawableAndWhatATruncatedFileLacks) {
  const fs::path dir = fs::temp_directory_path() / ("voltree_info_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string bytes = SerializeAsset(ThreeLevels());
  std::vector<size_t> ends;
  for (const auto& chunk : ListChunks(bytes, "t"))
    if (chunk.tag == "BBRD") ends.push_back(chunk.offset + chunk.stored_bytes);
  ASSERT_EQ(ends.size(), 3u);
  WriteFileAtomic(dir / "tree.vtree", bytes);
  test::Outcome outcome = test::VoltreeCaptured("info '" + (dir / "tree.vtree").string() + "'");
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  for (size_t l = 0; l < 3; ++l)
    EXPECT_NE(outcome.output.find("  level " + std::to_string(l) + ": " + std::to_string(ends[l]) + " bytes\n"),
              std::string::npos)
        << outcome.output;
  EXPECT_EQ(outcome.output.find("warning"), std::string::npos) << outcome.output;

  const size_t cut = ends[1] + 30;  // inside level 2's CELL chunk
  WriteFileAtomic(dir / "cut.vtree", bytes.substr(0, cut));
  outcome = test::VoltreeCaptured("info '" + (dir / "cut.vtree").string() + "'");
  EXPECT_EQ(outcome.status, 0) << outcome.output;
  for (const std::string& expected :
       {"warning: truncated file: levels 2..2 of 0..2 are missing: the file ends at byte " + std::to_string(cut) +
            ", inside the CELL chunk of level 2 that starts at byte " + std::to_string(ends[1]),
        "CELL at byte " + std::to_string(ends[1]) + ": cut off, the file ends at byte " + std::to_string(cut),
        "  level 1: " + std::to_string(ends[1]) + " bytes\n",
        "the file ends at byte " + std::to_string(cut) + "; levels 2..2 are missing"})
    EXPECT_NE(outcome.output.find(expected), std::string::npos) << expected << "\n" << outcome.output;
  EXPECT_EQ(outcome.output.find("  level 2:"), std::string::npos) << outcome.output;

  // Before level 0 is whole there is nothing to describe.
  WriteFileAtomic(dir / "head.vtree", bytes.substr(0, ends[0] - 1));
  outcome = test::VoltreeCaptured("info '" + (dir / "head.vtree").string() + "'");
  EXPECT_EQ(outcome.status, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("head.vtree"), std::string::npos) << outcome.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace voltree
