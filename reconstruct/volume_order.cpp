#include "reconstruct/volume_order.h"

#include <algorithm>

#include "core/error.h"
#include "reconstruct/grid.h"

namespace voltree {
namespace {

// children[k][i]: indices into level k+1 of the children of cell i of level k, in storage order.
using ChildLists = std::vector<std::vector<std::vector<uint32_t>>>;

ChildLists ChildrenDownTo(const Volume& volume, int level) {
  ChildLists children(level);
  for (int k = 0; k < level; ++k) {
    const auto& parents = volume.levels[k].cells;
    const auto& cells = volume.levels[k + 1].cells;
    children[k].resize(parents.size());
    for (uint32_t i = 0; i < cells.size(); ++i) {
      const CellCoord parent{uint16_t(cells[i][0] / volume.branching), uint16_t(cells[i][1] / volume.branching),
                             uint16_t(cells[i][2] / volume.branching)};
      const auto it = std::lower_bound(parents.begin(), parents.end(), parent, CellLess);
      if (it == parents.end() || *it != parent)
        Fail("volume: level ", k + 1, " cell ", i, " has no parent cell in level ", k);
      children[k][size_t(it - parents.begin())].push_back(i);
    }
  }
  return children;
}

}  // namespace

std::vector<uint32_t> BackToFrontCells(const Volume& volume, int level, const Eigen::Vector3d& eye) {
  if (level < 0 || level >= int(volume.levels.size()))
    Fail("volume: level ", level, " is outside 0..", int(volume.levels.size()) - 1);
  const ChildLists children = ChildrenDownTo(volume, level);
  std::vector<uint32_t> out;
  out.reserve(volume.levels[level].cells.size());
  auto far_to_near = [&](int k, std::vector<uint32_t>& cells) {
    std::sort(cells.begin(), cells.end(), [&](uint32_t a, uint32_t b) {
      const double da = (volume.CellCenter(k, volume.levels[k].cells[a]) - eye).norm();
      const double db = (volume.CellCenter(k, volume.levels[k].cells[b]) - eye).norm();
      return da != db ? da > db : a < b;
    });
  };
  auto visit = [&](auto&& self, int k, uint32_t cell) -> void {
    if (k == level) {
      out.push_back(cell);
      return;
    }
    std::vector<uint32_t> next = children[k][cell];
    far_to_near(k + 1, next);
    for (uint32_t child : next) self(self, k + 1, child);
  };
  std::vector<uint32_t> roots(volume.levels[0].cells.size());
  for (uint32_t i = 0; i < roots.size(); ++i) roots[i] = i;
  far_to_near(0, roots);
  for (uint32_t root : roots) visit(visit, 0, root);
  return out;
}

}  // namespace voltree
