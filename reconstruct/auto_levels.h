// `--levels auto`: as many levels as the photos can fill. The finest level is the first whose
// billboard texel, seen from the median photo at the volume centre's depth, covers at most one
// photo pixel; finer levels would hold detail no photo has.
#pragma once

#include <optional>

#include "reconstruct/opacity.h"
#include "reconstruct/reconstruct.h"

namespace voltree {

// Hierarchy levels (root included) for these photos and bounds at options' branching, texels
// and margin. Throws Error naming the photo size when it supports fewer than 3 levels.
int LevelsForPhotos(const ReconstructInput& input, const ReconstructOptions& options);

// How deep ReconstructOptions::deepen_within_bytes may take the octree: as many levels as the
// photos fill and the memory available holds, never fewer than options.levels.
int DeepeningCeiling(const ReconstructInput& input, const ReconstructOptions& options);

// The deepening rule for `options` (null when deepen_within_bytes is 0 or auto_levels is set):
// a billboard is taken to cost 2 bytes (the demo oak: 1.90 at the 16 / 1024 codewords it keeps,
// 1.61 at 64 / 64) and every view to keep a billboard in every cell (pruning keeps about 22 of
// 24), which leaves room for a level that grows faster than the rule's 4 times.
std::optional<DeepeningRule> DeepeningFor(const ReconstructInput& input, const ReconstructOptions& options);

// `options` with levels resolved when auto_levels is set (unchanged otherwise).
ReconstructOptions ResolveLevels(const ReconstructInput& input, const ReconstructOptions& options);

}  // namespace voltree
