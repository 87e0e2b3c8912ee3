// The hierarchy's geometry: a root cube split `branching` times per axis per level, and the kept
// cells of one level addressed compactly (sorted integer coordinates) with an O(1) lookup.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace voltree {

using CellCoord = std::array<uint16_t, 3>;

struct GridFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // min corner of the root cube
  double size = 1;                                   // root cube edge
  int branching = 2;

  int Resolution(int level) const;  // branching^level
  double CellSize(int level) const { return size / Resolution(level); }
  Eigen::Vector3d CellMin(int level, const CellCoord& c) const {
    return origin + CellSize(level) * Eigen::Vector3d(c[0], c[1], c[2]);
  }
  Eigen::Vector3d CellCenter(int level, const CellCoord& c) const {
    return origin + CellSize(level) * Eigen::Vector3d(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5);
  }
};

// The bounding cube of [bounds_min, bounds_max], centred on it, grown by `margin` (a fraction of
// the largest extent) on every side so that leaves on the boundary do not sit on cell faces.
GridFrame RootCube(const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max, double margin, int branching);

// branching^level, or 0 when it would not fit the 16-bit cell coordinates.
int64_t LevelResolution(int branching, int level);

// Cells sort by (z, y, x): the same order as the dense index.
inline uint64_t LinearKey(const CellCoord& c, int resolution) {
  return (uint64_t(c[2]) * resolution + c[1]) * resolution + c[0];
}
inline bool CellLess(const CellCoord& a, const CellCoord& b) {
  return std::array{a[2], a[1], a[0]} < std::array{b[2], b[1], b[0]};
}

// The kept cells of one level: sorted coordinates plus a dense index grid for ray traversal
// (resolution^3 int32, -1 for carved cells), and the bounding box of the kept cells.
class LevelCells {
 public:
  LevelCells() = default;
  // `cells` must be sorted by CellLess without duplicates.
  LevelCells(int resolution, std::vector<CellCoord> cells);

  int resolution() const { return resolution_; }
  size_t size() const { return cells_.size(); }
  const std::vector<CellCoord>& cells() const { return cells_; }
  const CellCoord& cell(size_t i) const { return cells_[i]; }
  // Index of the kept cell at (x, y, z), or -1.
  int32_t Find(int x, int y, int z) const { return index_[(size_t(z) * resolution_ + y) * resolution_ + x]; }
  // Kept-cell bounds in cell units: [box_min, box_max) per axis.
  const std::array<int, 3>& box_min() const { return box_min_; }
  const std::array<int, 3>& box_max() const { return box_max_; }

  static size_t DenseBytes(int64_t resolution) {
    return size_t(resolution) * resolution * resolution * sizeof(int32_t);
  }

 private:
  int resolution_ = 0;
  std::vector<CellCoord> cells_;
  std::vector<int32_t> index_;
  std::array<int, 3> box_min_{0, 0, 0};
  std::array<int, 3> box_max_{0, 0, 0};
};

// The children of `cells` (sorted) at the next level, sorted.
std::vector<CellCoord> Children(const std::vector<CellCoord>& cells, int branching);

}  // namespace voltree
