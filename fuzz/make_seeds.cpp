// Writes small valid .vtree files (prefixed with the fuzzer's option byte) into a corpus folder.
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/files.h"
#include "core/vtree.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vtree_fuzz_seeds CORPUS_DIR\n");
    return 1;
  }
  using namespace voltree;
  VtreeAsset asset;
  asset.texels = 4;
  asset.views = {{"a.png", {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}}, {"b.png", {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}};
  for (uint32_t l = 0; l < 2; ++l) {
    VtreeLevel level;
    level.resolution = 1u << l;
    level.cells = {{0, 0, 0}};
    level.density = {1.5f};
    level.billboards = {{0, 0, 1, 0}, {0, 1, 0, 1}};
    level.billboards_before_pruning = 2;
    asset.levels.push_back(level);
  }
  asset.colour_codebook_size = 2;
  asset.alpha_codebook_size = 2;
  asset.atlas = {8, 4, 4, 2, 2, std::vector<uint8_t>(32, 0x5A)};
  // A third level whose cells are out of (z, y, x) order: stored explicitly, not as child masks.
  VtreeLevel explicit_cells;
  explicit_cells.resolution = 4;
  explicit_cells.cells = {{1, 1, 0}, {0, 0, 0}};
  explicit_cells.density = {0.5f, 2.0f};
  explicit_cells.billboards = {{0, 1, 1, 1}, {1, 0, 0, 0}, {1, 1, 1, 0}};
  explicit_cells.billboards_before_pruning = 4;
  VtreeAsset three_levels = asset;
  three_levels.levels.push_back(explicit_cells);
  std::filesystem::create_directories(argv[1]);
  int seed = 0;
  for (const VtreeAsset* tree : {&asset, &three_levels})
    for (int variant = 0; variant < 16; ++variant) {
      VtreeWriteOptions options;
      options.zstd = variant & 8;
      std::string bytes = std::string(1, char(variant & 7)) + SerializeAsset(*tree, options);
      if (variant & 2) bytes.resize(bytes.size() - 7);  // partial reads: the last level cut off
      WriteFileAtomic(std::filesystem::path(argv[1]) / ("seed_" + std::to_string(seed++) + ".vtree"), bytes);
    }
  return 0;
}
