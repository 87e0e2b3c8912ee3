// Background told by parallax. Once the cameras are known, a neighbouring photo predicts what lies
// behind the tree: the distant backdrop (sky, clouds, skyline) moves as if at infinity, the ground
// as the plane z = 0 of the tree frame. A pixel whose neighbourhood a neighbour photo shows again
// where either would put it is background, whatever its colour; the tree, in between, moves
// against both and is never explained (ARCHITECTURE's plane-induced homography, done per pixel so
// that lens distortion is honoured).
#pragma once

#include <vector>

#include "capture/matte/consistency.h"
#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct BackdropOptions {
  int neighbours = 2;  // nearest cameras asked; a pixel the tree hides in one may show in another
  // Patches of (2r+1)^2 pixels are compared. The sky is smooth and seen through a sparse crown in
  // gaps a few pixels wide: single pixels there. The ground is textured and as green as leaves:
  // a single pixel matched the oak's crown against grass (matte MSE 0.0059 -> 0.012), a patch
  // does not.
  int far_patch_radius = 0;
  int ground_patch_radius = 2;
  double max_difference = 0.04;  // mean absolute difference (sRGB, 0..1) still called the same
  double ground_z = 0;           // height of the ground plane in the views' frame (the tree frame: 0)
  // Behind the tree (ExplainedBehindHull): distant trees, hills and houses stand at no one depth.
  int behind_neighbours = 4;      // a sweep along the line is cheap once the hull rules out the tree
  int behind_patch_radius = 2;    // textured clutter: patches, as for the ground
  double behind_step_pixels = 1;  // the sweep's step along the neighbour's epipolar line
  // Neighbours that must show the patch at one depth. With one, among a thousand depths some
  // patch of grass or of a distant trunk matched the aspen's thin trunk, and the trunk was lost
  // (a veto by the neighbours that see that depth and show something else did not save it).
  int behind_min_views = 2;
  void Check() const;  // throws OptionError naming the field
};

// 255 where photo `target` is explained by the backdrop or the ground in a neighbouring photo, 0
// elsewhere (the tree, and whatever is neither far nor on the ground). `photos[i]` is views[i]'s
// RGB photo at its camera's size; `mattes[i]` (or none) its first matte, where the neighbour's
// ground counts as hidden.
Image8 ExplainedByBackdrop(const std::vector<View>& views, const std::vector<Image8>& photos,
                           const std::vector<Image8>& mattes, size_t target, const BackdropOptions& options);

// The third hypothesis, once a visual hull bounds the tree: what lies behind it. Each pixel of
// `region` in photo `target` not yet explained is swept along its ray from the hull's far side
// (hulls[target].far_depth) out to infinity, or to the ground where the ray meets it first; a
// neighbouring photo that shows the same patch where its own hull does not hide it explains it.
// The tree itself stands in front of every depth swept, so it is never explained: its patch would
// have to reappear outside the neighbour's hull. 255 where explained, 0 elsewhere; `hulls[i]`
// belongs to views[i].
Image8 ExplainedBehindHull(const std::vector<View>& views, const std::vector<Image8>& photos,
                           const std::vector<HullProjection>& hulls, size_t target, const Image8& region,
                           const BackdropOptions& options);

}  // namespace voltree
