// Back-to-front traversal of a .vtree octree.
//
// The asset stores every level as a list of integer cell coordinates; OctreeIndex links each
// cell to its children (the cells of the next level inside it) and to its billboards. Traversal
// starts at the level-0 cells, and at each node visits the children far-to-near from the camera
// position (sorted by distance from the eye to the child centre, decreasing; ties by index, so
// the order is deterministic). For equal cubes on a grid this is a valid visibility order: if a
// child A can hide a child B, the eye is on A's side of every plane separating them, so A's
// centre is strictly nearer. Subtrees are contiguous, so the order holds across levels too.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/vtree.h"
#include "render/lod.h"

namespace voltree {

class OctreeIndex {
 public:
  explicit OctreeIndex(const VtreeAsset& asset);  // throws Error when a cell has no parent

  int levels() const { return int(first_cell_.size()); }
  int branching() const { return branching_; }
  // Cells of all levels are numbered globally, root level first.
  uint32_t CellCount() const { return uint32_t(level_of_.size()); }
  uint32_t FirstCell(int level) const { return first_cell_[level]; }
  int LevelOf(uint32_t cell) const { return level_of_[cell]; }
  const Eigen::Vector3d& Center(uint32_t cell) const { return centre_[cell]; }
  double CellSize(int level) const { return cell_size_[level]; }
  // Children (global indices) of a cell, in storage order.
  const uint32_t* ChildrenBegin(uint32_t cell) const { return children_.data() + child_offset_[cell]; }
  const uint32_t* ChildrenEnd(uint32_t cell) const { return children_.data() + child_offset_[cell + 1]; }
  // Billboards (global indices: level by level as stored) of a cell.
  uint32_t BillboardsBegin(uint32_t cell) const { return billboard_offset_[cell]; }
  uint32_t BillboardsEnd(uint32_t cell) const { return billboard_offset_[cell + 1]; }
  const VtreeBillboard& Billboard(uint32_t index) const { return billboards_[index]; }
  uint32_t BillboardCount() const { return uint32_t(billboards_.size()); }
  // Global billboard index of (cell, view), or kNone when the view was pruned for that cell.
  static constexpr uint32_t kNone = 0xffffffffu;
  uint32_t FindBillboard(uint32_t cell, uint16_t view) const;

 private:
  int branching_ = 2;
  std::vector<uint32_t> first_cell_;  // per level
  std::vector<int> level_of_;
  std::vector<Eigen::Vector3d> centre_;
  std::vector<double> cell_size_;
  std::vector<uint32_t> child_offset_, children_;
  std::vector<uint32_t> billboard_offset_;
  std::vector<VtreeBillboard> billboards_;  // cell field rewritten to global cell indices
};

struct TraversalCamera {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  double focal_pixels = 500;                            // for the LOD rules
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit view direction; needed by LodRule::kPlanes
};

// The distance the LOD rule measures a cell centre at (see lod.h).
double LodDistance(LodRule rule, const TraversalCamera& camera, const Eigen::Vector3d& centre);

// Emits the cells to draw (global indices), back to front, into `out` (cleared first). The
// visibility order always uses the Euclidean distance; only the LOD decision follows lod.rule.
// `refined`: optional per-cell LOD state across frames (CellCount() entries, 1 = refined last
// frame; resized and zeroed when its size is wrong), read for hysteresis and updated.
void TraverseBackToFront(const OctreeIndex& index, const TraversalCamera& camera, const LodOptions& lod, int texels,
                         std::vector<uint32_t>* out, std::vector<uint8_t>* refined = nullptr);

}  // namespace voltree
