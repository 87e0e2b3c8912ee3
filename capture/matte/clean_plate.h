// The ground behind the tree, pixel by pixel (a clean plate). Seen from above, the ground behind a
// gap in the crown lies well beside the crown in the neighbouring photos: a ray from a camera at
// 20° meets the ground far behind the tree. Where the neighbours' mattes leave that ground
// unhidden and two or more of them agree on its colour, that colour is what the pixel would show
// without the tree. Gaps a pixel or two wide, which a patch cannot test (backdrop.h) and whose
// window holds too few background pixels to average (mixed_pixels.h), are then told by colour.
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct CleanPlateOptions {
  int neighbours = 6;     // nearest cameras asked
  int min_views = 2;      // of them, at least this many must agree on the colour
  double agree = 0.04;    // mean absolute RGB difference (sRGB, 0..1) still called the same colour
  int hidden_margin = 2;  // a neighbour's matte grown by this many pixels hides the ground behind it
  double ground_z = 0;    // height of the ground plane in the views' frame (the tree frame: 0)
  void Check() const;     // throws OptionError naming the field
};

struct CleanPlate {
  ImageF colour;  // RGB in [0, 1] where known
  ImageF spread;  // the agreeing neighbours' RMS distance from their mean colour; -1 where unknown
  bool Known(int x, int y) const { return spread.at(x, y) >= 0; }
};

// The clean plate of photo `target` at the pixels where `region` (1 channel, its size) is nonzero.
// `photos[i]` is views[i]'s RGB photo, `mattes[i]` its matte (nonzero: the tree hides the ground
// behind).
CleanPlate GroundCleanPlate(const std::vector<View>& views, const std::vector<Image8>& photos,
                            const std::vector<Image8>& mattes, size_t target, const Image8& region,
                            const CleanPlateOptions& options);

}  // namespace voltree
