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
struct CleanPlate;  // clean_plate.h

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
  // Where the clean plate (clean_plate.h) knows the ground behind a pixel, a pixel within
  // `plate_match` of it (mean absolute RGB difference) and under `plate_background` of the way to
  // the purest tree colour near it is known background. A pixel whose colour lies within
  // `plate_line` (RGB distance) of the line from the plate to that colour, short of `pure`, is a
  // mix of the two and goes to the solver even where the matte made it whole; 0 (the default)
  // leaves whole pixels whole. Measured at 0.05 on the same cameras: the aspen at 20° gained
  // 0.15 dB held-out alpha, but the pine's matte error under the truth doubled (its needles lie
  // on the line from the grass) and its held-out recall fell from 0.974 to 0.940.
  // The plate's spread counts as at least `min_plate_spread` in the contrast test.
  double plate_background = 0.15;
  double plate_match = 0.04;
  double plate_line = 0;
  double min_plate_spread = 0.01;
  void Check() const;  // throws OptionError naming the field
};

// `matte` (1 channel) of `photo` (RGB) matted again: background where it was, and the clear sky;
// known tree where it was whole and its colour is pure; the solver (`matte_options`) in between.
Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const MatteOptions& matte_options,
                        const MixedPixelOptions& options);

// The same with the photo's sky already estimated (matte::EstimatePhotoSky with `matte_options`),
// for a caller that needs it too, and the background known to it: `clear_sky` (255 where the
// photo certainly shows sky, SkyEstimate::ClearSky) stays background; nullptr leaves the sky to
// the solver; where `plate` (or none) knows the ground behind a pixel, the pixel is judged against
// it, and one that shows it is background.
Image8 MatteMixedPixels(const Image8& photo, const Image8& matte, const matte::SkyEstimate& sky,
                        const Image8* clear_sky, const CleanPlate* plate, const MatteOptions& matte_options,
                        const MixedPixelOptions& options);

}  // namespace voltree
