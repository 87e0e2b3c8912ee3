// The coverage guard: a matte that covers most of the frame (the ground or the sky taken for the
// tree) or almost nothing (no tree found, or a photo without one) cannot be right, and every later
// stage would build on it. Checked on the whole set so the message names every such photo.
#pragma once

#include <string>
#include <vector>

#include "core/image.h"

namespace voltree {

struct MatteCoverageLimits {
  // Mean alpha over the frame. The studio frames the tree's bounds with a margin and its true
  // mattes cover little of the frame (oak: 11-12 %), so 0.75 leaves room for a tree photographed
  // close up while catching a ground or sky taken for the tree.
  double max_coverage = 0.75;
  double min_coverage = 0.002;  // 0.2 %: a 512-px photo's tree smaller than about 23 x 23 pixels
  void Check() const;           // throws Error naming the field
};

// Mean alpha of a 1-channel 8-bit matte, in [0, 1].
double MatteCoverage(const Image8& matte);

struct NamedCoverage {
  std::string name;  // the photo
  double coverage = 0;
};

// Throws Error naming the photos whose coverage is outside the limits and what to try; `source`
// says where the mattes came from ("computed", or the user's folder) so the advice fits.
void CheckMatteCoverage(const std::vector<NamedCoverage>& mattes, const MatteCoverageLimits& limits,
                        const std::string& source, bool computed);

}  // namespace voltree
