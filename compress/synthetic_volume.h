// Synthetic Volumes for tests and benchmarks when no reconstruction is at hand: an octree whose
// billboards have smooth leaf-like textures (greens, yellow-greens, bark browns, a few sunlit
// highlights and deep shadows) and soft blob-shaped alpha masks with transparent texels.
#pragma once

#include <cstdint>

#include "core/volume.h"

namespace voltree {

struct SyntheticVolumeOptions {
  int levels = 4;
  int views = 12;
  int billboards = 4000;  // spread over the levels, finer levels get more
  int texels = 4;
  uint64_t seed = 7;
};

Volume MakeSyntheticVolume(const SyntheticVolumeOptions& options);

}  // namespace voltree
