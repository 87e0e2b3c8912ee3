// Where the studio's cameras stand: rings around the tree at different elevations, all looking at
// the centre of its bounds from a distance at which the whole tree fits in the frame.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "samples/studio_options.h"

namespace voltree {

struct StudioRig {
  std::vector<View> inputs;    // named view_000.png, ...
  std::vector<View> held_out;  // named held_000.png, ...
  double distance = 0;         // from each camera to the target
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

// Input views: ring r of R sits at an elevation spaced evenly from the lowest to the highest ring,
// its azimuths evenly spaced and staggered between rings. Held-out views sit between rings (or
// above a single ring) at azimuths halfway between input views.
StudioRig MakeStudioRig(const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max,
                        const StudioOptions& options);

}  // namespace voltree
