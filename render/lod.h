// Level of detail: which octree level to draw where.
//
// Screen-space rule: keep descending while one texel of a cell's billboard would cover more than
// `max_texel_pixels` pixels at the cell's distance (Linz 2006 uses distance planes orthogonal to
// the view direction; the Euclidean distance to the cell centre is rotation invariant and makes
// the choice depend on the camera position only). The decision is monotone in distance, so as
// the camera moves away the drawn level never increases.
// Popping: the switch is per cell and immediate (no cross-fade), but with hysteresis when the
// caller keeps per-cell state across frames: a cell refines when its texel exceeds
// max_texel_pixels * (1 + hysteresis) and coarsens only below max_texel_pixels * (1 - hysteresis),
// so a camera hovering at a threshold does not make cells flicker between levels.
#pragma once

namespace voltree {

struct LodOptions {
  int forced_level = -1;          // >= 0: draw exactly this level (clamped to the finest level)
  double max_texel_pixels = 1.0;  // descend while a texel covers more pixels than this
  double hysteresis = 0.15;       // relative band around the threshold (used with per-cell state)
  void Check() const;
};

// Projected size in pixels of one texel of a cell of edge `cell_size` with `texels` per side at
// `distance` from a camera with focal length `focal_pixels`.
double TexelPixels(double cell_size, int texels, double distance, double focal_pixels);

// Whether a node at `level` (of `finest_level`) should be replaced by its children.
// `previous`: -1 without history, else whether the cell was refined in the previous frame.
bool ShouldDescend(const LodOptions& options, int level, int finest_level, double cell_size, int texels,
                   double distance, double half_diagonal, double focal_pixels, int previous = -1);

}  // namespace voltree
