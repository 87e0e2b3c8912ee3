#include "render/traversal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/error.h"

namespace voltree {
namespace {

uint64_t Key(uint32_t x, uint32_t y, uint32_t z) { return (uint64_t(x) << 42) | (uint64_t(y) << 21) | z; }

}  // namespace

OctreeIndex::OctreeIndex(const VtreeAsset& asset) : branching_(asset.branching) {
  if (branching_ < 2) Fail("render: asset branching must be >= 2, got ", branching_);
  const int levels = int(asset.levels.size());
  uint32_t total = 0;
  for (int l = 0; l < levels; ++l) {
    first_cell_.push_back(total);
    total += uint32_t(asset.levels[l].cells.size());
  }
  level_of_.resize(total);
  centre_.resize(total);
  for (int l = 0; l < levels; ++l) {
    const VtreeLevel& level = asset.levels[l];
    const double size = asset.size / level.resolution;
    cell_size_.push_back(size);
    for (size_t i = 0; i < level.cells.size(); ++i) {
      const auto& c = level.cells[i];
      level_of_[first_cell_[l] + i] = l;
      centre_[first_cell_[l] + i] =
          asset.origin + size * (Eigen::Vector3d(c[0], c[1], c[2]) + Eigen::Vector3d::Constant(0.5));
    }
  }
  // Children: counting sort of each level's cells by parent (stable: storage order kept).
  std::vector<uint32_t> parent(total, kNone);
  for (int l = 1; l < levels; ++l) {
    std::unordered_map<uint64_t, uint32_t> above;  // lookups only; never iterated
    const VtreeLevel& up = asset.levels[l - 1];
    above.reserve(up.cells.size());
    for (size_t i = 0; i < up.cells.size(); ++i)
      above.emplace(Key(up.cells[i][0], up.cells[i][1], up.cells[i][2]), first_cell_[l - 1] + uint32_t(i));
    const VtreeLevel& level = asset.levels[l];
    for (size_t i = 0; i < level.cells.size(); ++i) {
      const auto& c = level.cells[i];
      const auto it = above.find(Key(c[0] / branching_, c[1] / branching_, c[2] / branching_));
      if (it == above.end())
        Fail("render: level ", l, " cell ", i, " (", c[0], ",", c[1], ",", c[2], ") has no parent cell in level ",
             l - 1);
      parent[first_cell_[l] + i] = it->second;
    }
  }
  child_offset_.assign(total + 1, 0);
  for (uint32_t c = 0; c < total; ++c)
    if (parent[c] != kNone) ++child_offset_[parent[c] + 1];
  for (uint32_t c = 0; c < total; ++c) child_offset_[c + 1] += child_offset_[c];
  children_.resize(child_offset_[total]);
  std::vector<uint32_t> fill(child_offset_.begin(), child_offset_.end() - 1);
  for (uint32_t c = 0; c < total; ++c)
    if (parent[c] != kNone) children_[fill[parent[c]]++] = c;
  // Billboards, level by level; each level's list is sorted by (cell, view).
  billboard_offset_.assign(total + 1, 0);
  for (int l = 0; l < levels; ++l)
    for (const VtreeBillboard& b : asset.levels[l].billboards) {
      if (b.cell >= asset.levels[l].cells.size()) Fail("render: level ", l, " billboard names missing cell ", b.cell);
      VtreeBillboard global = b;
      global.cell = first_cell_[l] + b.cell;
      ++billboard_offset_[global.cell + 1];
      billboards_.push_back(global);
    }
  std::stable_sort(billboards_.begin(), billboards_.end(),
                   [](const VtreeBillboard& a, const VtreeBillboard& b) { return a.cell < b.cell; });
  for (uint32_t c = 0; c < total; ++c) billboard_offset_[c + 1] += billboard_offset_[c];
}

double LodDistance(LodRule rule, const TraversalCamera& camera, const Eigen::Vector3d& centre) {
  return rule == LodRule::kPlanes ? (centre - camera.eye).dot(camera.direction) : (centre - camera.eye).norm();
}

uint32_t OctreeIndex::FindBillboard(uint32_t cell, uint16_t view) const {
  for (uint32_t i = billboard_offset_[cell]; i < billboard_offset_[cell + 1]; ++i)
    if (billboards_[i].view == view) return i;
  return kNone;
}

namespace {

struct Traverser {
  const OctreeIndex& index;
  const TraversalCamera& camera;
  const LodOptions& lod;
  int texels;
  std::vector<uint32_t>* out;
  std::vector<uint8_t>* refined;

  double Distance(uint32_t cell) const { return (index.Center(cell) - camera.eye).norm(); }

  // Sorts `cells` far-to-near in place.
  void SortFarToNear(uint32_t* begin, uint32_t* end) const {
    std::sort(begin, end, [&](uint32_t a, uint32_t b) {
      const double da = Distance(a), db = Distance(b);
      return da != db ? da > db : a < b;
    });
  }

  void ForgetSubtree(uint32_t cell) const {
    for (const uint32_t* child = index.ChildrenBegin(cell); child != index.ChildrenEnd(cell); ++child)
      if ((*refined)[*child]) {
        (*refined)[*child] = 0;
        ForgetSubtree(*child);
      }
  }

  void Visit(uint32_t cell) const {
    const int level = index.LevelOf(cell);
    const double size = index.CellSize(level);
    const bool has_children = index.ChildrenBegin(cell) != index.ChildrenEnd(cell);
    const int previous = refined ? (*refined)[cell] : -1;
    const bool descend = has_children && ShouldDescend(lod, level, index.levels() - 1, size, texels,
                                                       LodDistance(lod.rule, camera, index.Center(cell)),
                                                       0.5 * std::sqrt(3.0) * size, camera.focal_pixels, previous);
    if (refined) {
      if (previous == 1 && !descend) ForgetSubtree(cell);  // stale history would bias a later refine
      (*refined)[cell] = descend;
    }
    if (descend) {
      std::vector<uint32_t> children(index.ChildrenBegin(cell), index.ChildrenEnd(cell));
      SortFarToNear(children.data(), children.data() + children.size());
      for (uint32_t child : children) Visit(child);
      return;
    }
    // A leaf above the forced level has nothing of that level to show.
    if (lod.forced_level >= 0 && level < std::min(lod.forced_level, index.levels() - 1)) return;
    out->push_back(cell);
  }
};

}  // namespace

void TraverseBackToFront(const OctreeIndex& index, const TraversalCamera& camera, const LodOptions& lod, int texels,
                         std::vector<uint32_t>* out, std::vector<uint8_t>* refined) {
  out->clear();
  if (lod.rule == LodRule::kPlanes && lod.forced_level < 0 && std::abs(camera.direction.norm() - 1) > 1e-6)
    Fail("render: the planes LOD rule needs a unit view direction");
  if (index.levels() == 0) return;
  if (refined && refined->size() != index.CellCount()) refined->assign(index.CellCount(), 0);
  const Traverser traverser{index, camera, lod, texels, out, refined};
  std::vector<uint32_t> roots;
  for (uint32_t c = index.FirstCell(0); c < (index.levels() > 1 ? index.FirstCell(1) : index.CellCount()); ++c)
    roots.push_back(c);
  traverser.SortFarToNear(roots.data(), roots.data() + roots.size());
  for (uint32_t root : roots) traverser.Visit(root);
}

}  // namespace voltree
