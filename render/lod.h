// Level of detail: which octree level to draw where.
//
// Both rules descend while one texel of a cell's billboard would cover more than
// `max_texel_pixels` pixels; they differ in the distance that size is measured at.
// - kScreen: the Euclidean distance from the eye to the cell centre. Rotation invariant: turning
//   the camera on the spot never changes the levels, only moving it does.
// - kPlanes (Linz 2006): the depth of the cell centre along the view direction, i.e. its distance
//   to the camera plane. The level is then constant between planes orthogonal to the view
//   direction at depths d_L = focal * cell_size(L) / (texels * max_texel_pixels) (LodPlaneDepth):
//   cells in the slab [d_L, d_{L-1}) draw level L. This is the pinhole's exact size for a
//   camera-facing billboard (f * size / depth), so off-axis cells get the same texel budget as
//   central ones; turning the camera moves the planes with it.
// A cell the eye is inside of (or, for planes, a cell straddling the camera plane) always
// descends; a cell wholly behind the camera plane never does (it is not seen, coarse is cheapest).
// Both decisions are monotone in their distance, so as the camera moves away along its view
// direction the drawn level never increases.
//
// Popping: the switch is per cell and immediate, but with hysteresis when the caller keeps
// per-cell state across frames: a cell refines when its texel exceeds max_texel_pixels *
// (1 + hysteresis) and coarsens only below max_texel_pixels * (1 - hysteresis), so a camera
// hovering at a threshold does not make cells flicker between levels. Because a level's texel is
// at most about one pixel when it is swapped, the swap changes little on screen. There is no
// cross-fade: drawing a parent and its children with complementary alpha is not an identity under
// the over operator (1 - (1 - t a_p)(1 - (1 - t) a_c) differs from both), so a fade band would
// darken or thin the crown inside the band; hysteresis is the clean part and is what we keep.
#pragma once

#include <string>

namespace voltree {

enum class LodRule { kScreen, kPlanes };

// "screen" / "planes"; throws Error listing the names otherwise.
LodRule LodRuleFromName(const std::string& name);
const char* LodRuleName(LodRule rule);

struct LodOptions {
  LodRule rule = LodRule::kScreen;
  int forced_level = -1;          // >= 0: draw exactly this level (clamped to the finest level)
  double max_texel_pixels = 1.0;  // descend while a texel covers more pixels than this
  double hysteresis = 0.15;       // relative band around the threshold (used with per-cell state)
  void Check() const;
};

// Projected size in pixels of one texel of a cell of edge `cell_size` with `texels` per side at
// `distance` from a camera with focal length `focal_pixels`.
double TexelPixels(double cell_size, int texels, double distance, double focal_pixels);

// kPlanes: depth along the view direction beyond which cells of edge `cell_size` are not refined
// (without hysteresis).
double LodPlaneDepth(const LodOptions& options, double cell_size, int texels, double focal_pixels);

// Whether a node at `level` (of `finest_level`) should be replaced by its children. `distance`
// is the rule's distance (Euclidean for kScreen, depth along the view direction for kPlanes,
// negative behind the camera plane).
// `previous`: -1 without history, else whether the cell was refined in the previous frame.
bool ShouldDescend(const LodOptions& options, int level, int finest_level, double cell_size, int texels,
                   double distance, double half_diagonal, double focal_pixels, int previous = -1);

}  // namespace voltree
