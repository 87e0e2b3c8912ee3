// Billboard textures for every level, every kept cell and every input view, and their pruning.
//
// The billboard of cell c for view v is a square of side scale * cell edge centred on the cell,
// parallel to v's image plane: texel rows run along the view's "up" (image -Y), columns along
// image +X, texel (0,0) at the top-left. For each texel, the ray from camera v through the texel
// centre crosses the level's cells j with lengths l_j. With b the optical depth of the photo's
// alpha averaged over the texel's footprint,
//   gamma = b / sum_j sigma_j l_j   (all cells j on the ray at this level)
//   a_c   = 1 - exp(-gamma sigma_c l_c)
// so the product of (1 - a_j) along the ray is exp(-b) = 1 - alpha: compositing the billboards
// reproduces the photo. (Summing only the cells in front of c and c itself, a literal reading of
// the spec, hands the whole alpha to the front-most cell and makes compositing overshoot.)
// Texel colour = the foreground's straight colour over the same footprint, premultiplied by a_c.
// Pruning: a texel whose accumulated alpha in front, 1 - exp(-gamma sum_{j in front} sigma_j l_j),
// exceeds `prune` gets alpha 0; a billboard whose texels are all <= 1/255 is dropped.
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/progress.h"
#include "reconstruct/matte_stats.h"
#include "reconstruct/optical_depth.h"
#include "core/volume.h"

namespace voltree {

struct BillboardOptions {
  double prune = 0.995;                   // accumulated alpha in front above which a texel is hidden
  double scale = 1.0;                     // billboard side / cell edge
  double epsilon = kDefaultAlphaEpsilon;  // of the optical depth; must be the tomography's (optical_depth.h)

  void Check() const;  // throws OptionError naming the field
};

// The view's billboard frame, tree frame: camera centre, unit +Z, unit image "up" (-Y).
VolumeView MakeVolumeView(const View& view);

// Texel centre (row, col) of the billboard of the cell centred at `centre` with side `side`.
Eigen::Vector3d TexelCenter(const VolumeView& view, const Eigen::Vector3d& centre, double side, int texels, int row,
                            int col);

// Fills billboards, texels and billboards_before_pruning of every level of `volume`, whose
// geometry, views and densities are set. `foreground[v]`: premultiplied RGBA of view v.
void MakeBillboards(const std::vector<View>& views, const std::vector<MatteStats>& mattes,
                    const std::vector<Image8>& foreground, const BillboardOptions& options, Volume* volume,
                    Progress* progress);

}  // namespace voltree
