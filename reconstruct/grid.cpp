#include "reconstruct/grid.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

int GridFrame::Resolution(int level) const {
  const int64_t r = LevelResolution(branching, level);
  if (r == 0) Fail("level ", level, " at branching ", branching, " exceeds the 16-bit cell coordinates");
  return int(r);
}

int64_t LevelResolution(int branching, int level) {
  int64_t r = 1;
  for (int i = 0; i < level; ++i) {
    r *= branching;
    if (r > 65535) return 0;
  }
  return r;
}

GridFrame RootCube(const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max, double margin, int branching) {
  const Eigen::Vector3d extent = bounds_max - bounds_min;
  if (!extent.allFinite() || extent.minCoeff() < 0 || extent.maxCoeff() <= 0)
    Fail("scene bounds must be finite with bounds_max >= bounds_min and a positive extent");
  GridFrame frame;
  frame.branching = branching;
  frame.size = extent.maxCoeff() * (1 + 2 * margin);
  frame.origin = 0.5 * (bounds_min + bounds_max) - Eigen::Vector3d::Constant(0.5 * frame.size);
  return frame;
}

LevelCells::LevelCells(int resolution, std::vector<CellCoord> cells)
    : resolution_(resolution), cells_(std::move(cells)), index_(size_t(resolution) * resolution * resolution, -1) {
  box_min_ = {resolution, resolution, resolution};
  box_max_ = {0, 0, 0};
  for (size_t i = 0; i < cells_.size(); ++i) {
    const CellCoord& c = cells_[i];
    index_[LinearKey(c, resolution)] = int32_t(i);
    for (int a = 0; a < 3; ++a) {
      box_min_[a] = std::min<int>(box_min_[a], c[a]);
      box_max_[a] = std::max<int>(box_max_[a], c[a] + 1);
    }
  }
}

std::vector<CellCoord> Children(const std::vector<CellCoord>& cells, int branching) {
  std::vector<CellCoord> children;
  children.reserve(cells.size() * branching * branching * branching);
  for (const CellCoord& c : cells)
    for (int z = 0; z < branching; ++z)
      for (int y = 0; y < branching; ++y)
        for (int x = 0; x < branching; ++x)
          children.push_back(
              {uint16_t(c[0] * branching + x), uint16_t(c[1] * branching + y), uint16_t(c[2] * branching + z)});
  std::sort(children.begin(), children.end(), CellLess);
  return children;
}

}  // namespace voltree
