// A trunk the mattes lose before it reaches the ground. At the aspen's foot grey bark stands
// against grey soil, and when most first mattes miss that stretch every hull carves it: the mends
// (narrow_parts.h), which look inside a hull, have nothing to bring back, the bounds end above
// the ground and no view of the volume holds the trunk's foot. A tree stands on the ground. When
// the hull of all mattes ends well above the ground plane, its lowest slice is carried straight
// down to it, and in each photo where that stretch stands in front of the ground (its pixels
// unlike the clean plate, clean_plate.h, the ground the neighbours see behind it) its centre line
// becomes known tree and the solver decides its width from the photo's colours.
#pragma once

#include <string>
#include <vector>

#include "capture/matte/clean_plate.h"
#include "capture/matte/options.h"
#include "capture/normalize_hull.h"
#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct TrunkFootOptions {
  HullOptions hull;           // the hull whose foot is measured (the one the bounds are found from)
  double ground_z = 0;        // height of the ground plane in the views' frame (the tree frame: 0)
  double min_lift = 0.05;     // a foot this share of the hull's height above the ground, or more, is carried down
  double min_known = 0.3;     // share of the stretch's centre line where the plate must be known
  double min_in_front = 0.6;  // and share of those pixels unlike it (something stands in front)
  double unlike = 0.04;       // mean absolute RGB difference from the plate (sRGB, 0..1) that is unlike it
  double max_held = 0.5;      // a matte that already holds more of the centre line is left alone
  void Check() const;         // throws OptionError naming the field
};

// Carries the trunk down to the ground in the mattes that lose it; returns those photos' names.
// `photos[i]` (RGB) and `mattes[i]` (1 channel, replaced) belong to views[i]; the plate is found
// along the stretch with `plate_options`.
std::vector<std::string> CarryTrunkToGround(const std::vector<View>& views, const std::vector<Image8>& photos,
                                            const MatteOptions& matte_options, const CleanPlateOptions& plate_options,
                                            const TrunkFootOptions& options, std::vector<Image8>& mattes);

}  // namespace voltree
