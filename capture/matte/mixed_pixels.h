// Pixels the tree covers only in part. A leaf smaller than a pixel mixes its colour with what lies
// behind it; where that background is known, the mix tells how much of the pixel is tree: the
// colour's distance from the background against that of the purest tree colour near it (its
// purity). Matted again with only the pure pixels as known foreground, the solver decides the
// mixed ones, which a first matte (and the hull's re-matting, seeded by it) had made whole.
#pragma once

#include "capture/matte/options.h"
#include "core/image.h"

namespace voltree {

namespace matte {
struct SkyEstimate;  // sky_estimate.h
}  // namespace matte

struct MixedPixelOptions {
  // Below the sky (or where there is none), the background seen through the crown's gaps: the
  // mean of the matte's background pixels within `gap_radius`, trusted where at least
  // `min_gap_pixels` show it and the purest tree colour stands `min_contrast` times their colour
  // spread away from it (hills behind the crown are; grass as green as the leaves is not).
  int gap_radius = 7;
  int min_gap_pixels = 6;
  double min_contrast = 12.0;
  int tree_radius = 8;  // the purest tree colour is sought this far, among alpha >= 0.5
  double pure = 0.95;   // a pixel of alpha and purity at least this stays known tree
  void Check() const;   // throws OptionError naming the field
};

// `matte` (1 channel) of `photo` (RGB) matted again: background where it was, and the clear sky;
// known tree where it was whole and its colour is pure; the solver (`matte_options`) in between.
Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const MatteOptions& matte_options,
                        const MixedPixelOptions& options);

// The same with the photo's sky already estimated (matte::EstimatePhotoSky with `matte_options`),
// for a caller that needs it too, and the background known to it: `clear_sky` (255 where the
// photo certainly shows sky, SkyEstimate::ClearSky) stays background; nullptr leaves the sky to
// the solver.
Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const matte::SkyEstimate& sky,
                        const Image8* clear_sky, const MatteOptions& matte_options, const MixedPixelOptions& options);

}  // namespace voltree
