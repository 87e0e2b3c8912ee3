// The compact .vtree layout (format version 2): every way of storing cells and indices round-trips
// exactly, whatever the codebook sizes (index widths 0..16 bits), the branching and the cell order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>

#include "core/error.h"
#include "core/vtree.h"

namespace voltree {
namespace {

struct LayoutCase {
  int branching = 2;
  int levels = 3;
  uint32_t colour_codebook = 512, alpha_codebook = 512;
  bool sorted_cells = true;  // (z, y, x)-sorted children of the level above: stored as child masks
  int views = 5;
};

// A random asset: each level keeps some children of the level above, each cell some of its views.
VtreeAsset RandomAsset(const LayoutCase& c, uint32_t seed) {
  std::mt19937 rng(seed);
  VtreeAsset asset;
  asset.branching = c.branching;
  for (int v = 0; v < c.views; ++v) asset.views.push_back({"v" + std::to_string(v) + ".png"});
  asset.colour_codebook_size = c.colour_codebook;
  asset.alpha_codebook_size = c.alpha_codebook;
  const uint32_t tiles = std::max(c.colour_codebook, c.alpha_codebook), per_row = 16;
  const uint32_t rows = (tiles + per_row - 1) / per_row;
  asset.atlas = {per_row * 4, rows * 4, 4, per_row, tiles, std::vector<uint8_t>(size_t(per_row) * rows * 16, 7)};
  std::vector<std::array<uint16_t, 3>> parents = {{0, 0, 0}};
  uint32_t resolution = 1;
  for (int l = 0; l < c.levels; ++l) {
    VtreeLevel level;
    level.resolution = resolution;
    if (l == 0) {
      level.cells = parents;
    } else {
      const int b = c.branching;
      for (const auto& p : parents)
        for (int k = 0; k < b * b * b; ++k)
          if (rng() % 3 != 0)
            level.cells.push_back(
                {uint16_t(p[0] * b + k % b), uint16_t(p[1] * b + k / b % b), uint16_t(p[2] * b + k / (b * b))});
      std::sort(level.cells.begin(), level.cells.end(),
                [](const auto& a, const auto& b) { return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]); });
      if (!c.sorted_cells) std::shuffle(level.cells.begin(), level.cells.end(), rng);
    }
    for (size_t i = 0; i < level.cells.size(); ++i) {
      level.density.push_back(std::uniform_real_distribution<float>(0, 9)(rng));
      for (int v = 0; v < c.views; ++v)
        if (rng() % 4 != 0)
          level.billboards.push_back(
              {uint32_t(i), uint16_t(v), uint16_t(rng() % c.colour_codebook), uint16_t(rng() % c.alpha_codebook)});
    }
    level.billboards_before_pruning = level.billboards.size() + rng() % 7;
    parents = level.cells;
    resolution *= c.branching;
    asset.levels.push_back(level);
  }
  return asset;
}

void ExpectSameAsset(const VtreeAsset& a, const VtreeAsset& b) {
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (size_t l = 0; l < a.levels.size(); ++l) {
    const auto &x = a.levels[l], &y = b.levels[l];
    EXPECT_EQ(x.resolution, y.resolution);
    EXPECT_EQ(x.cells, y.cells) << "level " << l;
    EXPECT_EQ(x.density, y.density) << "level " << l;
    EXPECT_EQ(x.billboards_before_pruning, y.billboards_before_pruning);
    ASSERT_EQ(x.billboards.size(), y.billboards.size()) << "level " << l;
    for (size_t i = 0; i < x.billboards.size(); ++i) {
      const auto &p = x.billboards[i], &q = y.billboards[i];
      ASSERT_TRUE(p.cell == q.cell && p.view == q.view && p.colour == q.colour && p.alpha == q.alpha)
          << "level " << l << " billboard " << i;
    }
  }
  EXPECT_EQ(a.atlas.dxt5, b.atlas.dxt5);
}

TEST(VtreeLayout, EveryLayoutRoundTripsExactly) {
  std::vector<LayoutCase> cases;
  for (uint32_t size : {1u, 2u, 3u, 200u, 256u, 257u, 512u, 4097u, 65536u}) {
    LayoutCase c;
    c.colour_codebook = size;
    c.alpha_codebook = std::max(1u, size / 3);
    cases.push_back(c);
  }
  LayoutCase branching3;
  branching3.branching = 3;
  branching3.levels = 3;
  cases.push_back(branching3);
  LayoutCase unsorted;
  unsorted.sorted_cells = false;
  cases.push_back(unsorted);
  LayoutCase many_views;
  many_views.views = 13;  // view masks not a whole number of bytes per cell
  cases.push_back(many_views);
  uint32_t seed = 0;
  for (const LayoutCase& c : cases) {
    const VtreeAsset asset = RandomAsset(c, ++seed);
    for (bool zstd : {false, true}) {
      VtreeWriteOptions options;
      options.zstd = zstd;
      const std::string bytes = SerializeAsset(asset, options);
      const VtreeAsset back = ParseAsset(bytes, "tree.vtree");
      SCOPED_TRACE("codebooks " + std::to_string(c.colour_codebook) + ", branching " + std::to_string(c.branching) +
                   (c.sorted_cells ? "" : ", unsorted") + (zstd ? ", zstd" : ""));
      ExpectSameAsset(asset, back);
      EXPECT_EQ(SerializeAsset(back, options), bytes);
    }
  }
}

TEST(VtreeLayout, IndicesTakeTheBitsTheCodebooksNeed) {
  // Per billboard 9 + 9 bits for two codebooks of 512, plus one mask bit per cell and view: the
  // finest level's chunk is a fraction of the 10 bytes per billboard of format version 1.
  LayoutCase c;
  c.levels = 4;
  const VtreeAsset asset = RandomAsset(c, 99);
  const VtreeLevel& finest = asset.levels.back();
  const std::string bytes = SerializeAsset(asset);
  const auto chunks = ListChunks(bytes, "tree.vtree");
  const auto& bbrd = chunks.back();
  ASSERT_EQ(bbrd.tag, "BBRD");
  const uint64_t expected = 28 + 18 + (finest.cells.size() * c.views + 7) / 8 +
                            2 * (finest.billboards.size() + (finest.billboards.size() + 7) / 8);
  EXPECT_EQ(bbrd.stored_bytes, expected);
}

TEST(VtreeLayout, WriterRefusesWhatTheLayoutCannotHold) {
  VtreeAsset asset = RandomAsset({}, 5);
  auto& billboards = asset.levels[1].billboards;
  ASSERT_GE(billboards.size(), 2u);
  std::swap(billboards[0], billboards[1]);
  EXPECT_THROW(SerializeAsset(asset), Error);  // out of (cell, view) order
  std::swap(billboards[0], billboards[1]);
  billboards[0].colour = uint16_t(asset.colour_codebook_size);
  EXPECT_THROW(SerializeAsset(asset), Error);  // beyond the codebook: would not fit its bits
}

}  // namespace
}  // namespace voltree
