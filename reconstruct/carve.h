// Visual-hull carving: a cell is removed when some view sees all of it (its projection lies in
// the image, in front of the camera) and every pixel ray through its projection has alpha at or
// below the carving threshold. This is the conservative form of "cells crossed by empty rays are
// removed": a cell crossed by some empty rays but also by non-empty ones may still hold leaves.
#pragma once

#include <vector>

#include "core/camera.h"
#include "reconstruct/grid.h"
#include "reconstruct/matte_stats.h"

namespace voltree {

// The candidates (sorted) that survive carving, in the same order: a cell is removed when at
// least `empty_views` views see all of it empty.
std::vector<CellCoord> CarveCells(const GridFrame& frame, int level, const std::vector<CellCoord>& candidates,
                                  const std::vector<View>& views, const std::vector<MatteStats>& mattes,
                                  int empty_views = 1);

// The pixels a world-space box projects to (bounding rectangle of its 8 corners); false when a
// corner is behind the camera.
bool ProjectBox(const View& view, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double* min_x, double* min_y,
                double* max_x, double* max_y);

}  // namespace voltree
