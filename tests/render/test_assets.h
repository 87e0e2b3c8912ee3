// Hand-built .vtree assets for the render tests: every number in them is known, so a render of
// them has an exact expected image.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "core/camera.h"
#include "core/vtree.h"

namespace voltree::test {

// Cells only (no views, no billboards): every cell of `levels` levels over the root cube
// [-1,1]^2 x [0,2], for traversal and LOD tests.
inline VtreeAsset FullOctree(int levels) {
  VtreeAsset asset;
  asset.origin = Eigen::Vector3d(-1, -1, 0);
  asset.size = 2;
  asset.texels = 4;
  for (int l = 0; l < levels; ++l) {
    VtreeLevel level;
    level.resolution = 1u << l;
    for (uint16_t x = 0; x < level.resolution; ++x)
      for (uint16_t y = 0; y < level.resolution; ++y)
        for (uint16_t z = 0; z < level.resolution; ++z) level.cells.push_back({x, y, z});
    asset.levels.push_back(level);
  }
  return asset;
}

struct WhiteAssetOptions {
  int views = 4;                 // evenly spaced on a circle of radius 5 about the trunk
  double eye_height = 1.5;       // the views look at (0, 0, 1) from this height
  bool every_fine_cell = false;  // level 1: all 8 cells, or only the two diagonal ones
};

// Two levels over [-1,1]^2 x [0,2] whose billboards, one per cell and view, are opaque white
// (one 4x4 DXT5 tile).
inline VtreeAsset WhiteAsset(const WhiteAssetOptions& options = {}) {
  VtreeAsset asset;
  asset.origin = Eigen::Vector3d(-1, -1, 0);
  asset.size = 2;
  asset.texels = 4;
  asset.bounds_min = asset.origin;
  asset.bounds_max = Eigen::Vector3d(1, 1, 2);
  for (int v = 0; v < options.views; ++v) {
    const double a = 2 * std::numbers::pi * v / options.views;
    const Eigen::Vector3d eye(5 * std::cos(a), 5 * std::sin(a), options.eye_height);
    const Eigen::Matrix3d r =
        Pose::LookAt(eye, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ()).rotation.toRotationMatrix();
    asset.views.push_back({"view_" + std::to_string(v) + ".png", eye, r.row(2).transpose(), -r.row(1).transpose()});
  }
  asset.levels.resize(2);
  asset.levels[0].resolution = 1;
  asset.levels[0].cells = {{0, 0, 0}};
  asset.levels[1].resolution = 2;
  if (options.every_fine_cell) {
    asset.levels[1].cells = FullOctree(2).levels[1].cells;
  } else {
    asset.levels[1].cells = {{0, 0, 0}, {1, 1, 1}};
  }
  for (auto& level : asset.levels) {
    level.density.assign(level.cells.size(), 1.0f);
    for (uint32_t c = 0; c < level.cells.size(); ++c)
      for (int v = 0; v < options.views; ++v) level.billboards.push_back({c, static_cast<uint16_t>(v), 0, 0});
    level.billboards_before_pruning = level.billboards.size();
  }
  asset.colour_codebook_size = asset.alpha_codebook_size = 1;
  asset.atlas.width = asset.atlas.height = 4;
  asset.atlas.tiles_per_row = 1;
  asset.atlas.tile_count = 1;
  asset.atlas.dxt5 = {255, 255, 0, 0, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0xff, 0, 0, 0, 0};  // opaque white
  return asset;
}

}  // namespace voltree::test
