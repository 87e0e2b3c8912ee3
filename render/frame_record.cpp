#include "render/frame_record.h"

#include "core/error.h"

namespace voltree {

std::vector<uint32_t> PackCellCoordinates(const VtreeAsset& asset) {
  std::vector<uint32_t> codes;
  codes.reserve(asset.CellCount());
  for (size_t l = 0; l < asset.levels.size(); ++l) {
    const VtreeLevel& level = asset.levels[l];
    if (level.resolution > kMaxCellsPerAxis)
      Fail("render: level ", l, " has ", level.resolution, " cells per axis; the renderer draws at most ",
           kMaxCellsPerAxis, " (read the asset with a lower --max-level)");
    for (const auto& c : level.cells) codes.push_back(uint32_t(c[0]) | uint32_t(c[1]) << 10 | uint32_t(c[2]) << 20);
  }
  return codes;
}

}  // namespace voltree
