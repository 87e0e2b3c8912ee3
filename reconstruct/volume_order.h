// The order in which the renderer draws one level of a volume: back to front from an eye point.
// It is the renderer's traversal (render/traversal.h) with the level forced: from the root down,
// the children of every cell are visited far-to-near (distance from the eye to the child centre,
// decreasing; ties by index). Kept here so that whatever imitates the renderer on the CPU (the
// billboard fit, the error budget) composites in exactly the order the GPU does.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace voltree {

// Indices into volume.levels[level].cells, back to front as seen from `eye`.
std::vector<uint32_t> BackToFrontCells(const Volume& volume, int level, const Eigen::Vector3d& eye);

}  // namespace voltree
