// The reconstruction's result, `DIR/volume/` on disk: an octree of densities over the tree and,
// for every level, every kept cell and every input view, an n x n billboard texture.
// This is what compress/ consumes and what the uncompressed renderer draws.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace voltree {

// A billboard: the texture of one cell seen from one input view.
struct Billboard {
  uint32_t cell = 0;  // index into VolumeLevel::cells
  uint16_t view = 0;  // index into Volume::views
};

struct VolumeLevel {
  int resolution = 1;  // cells per axis at this level: branching^level
  std::vector<std::array<uint16_t, 3>>
      cells;                          // integer cell coordinates, kept (uncarved) cells only, sorted by (z, y, x)
  std::vector<float> density;         // sigma per cell, per unit length of the tree frame
  std::vector<Billboard> billboards;  // kept after pruning, sorted by (cell, view)
  // billboards.size() * texels * texels RGBA8 texels: sRGB, premultiplied alpha, row-major with
  // texel (0,0) at the billboard's top-left as seen from its view.
  std::vector<uint8_t> texels;
  size_t billboards_before_pruning = 0;
};

struct VolumeView {
  std::string name;                                      // the input image
  Eigen::Vector3d position = Eigen::Vector3d::Zero();    // camera center, tree frame
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit viewing direction (camera +Z)
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();         // unit camera -Y: billboard texel rows
};

struct Volume {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // min corner of the root cube
  double size = 1;                                   // edge length of the root cube
  int branching = 2;                                 // 2: octree, 3: tri-grid
  int texels = 4;                                    // n: billboards have n x n texels
  std::vector<VolumeView> views;
  std::vector<VolumeLevel> levels;  // levels[0] is the root

  double CellSize(int level) const { return size / levels.at(level).resolution; }
  Eigen::Vector3d CellCenter(int level, const std::array<uint16_t, 3>& cell) const {
    const double s = CellSize(level);
    return origin + s * Eigen::Vector3d(cell[0] + 0.5, cell[1] + 0.5, cell[2] + 0.5);
  }
  size_t BytesPerBillboard() const { return size_t(texels) * texels * 4; }
};

}  // namespace voltree
