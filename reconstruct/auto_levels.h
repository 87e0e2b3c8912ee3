// `--levels auto`: as many levels as the photos can fill. The finest level is the first whose
// billboard texel, seen from the median photo at the volume centre's depth, covers at most one
// photo pixel; finer levels would hold detail no photo has.
#pragma once

#include "reconstruct/reconstruct.h"

namespace voltree {

// Hierarchy levels (root included) for these photos and bounds at options' branching, texels
// and margin. Throws Error naming the photo size when it supports fewer than 3 levels.
int LevelsForPhotos(const ReconstructInput& input, const ReconstructOptions& options);

// `options` with levels resolved when auto_levels is set (unchanged otherwise).
ReconstructOptions ResolveLevels(const ReconstructInput& input, const ReconstructOptions& options);

}  // namespace voltree
