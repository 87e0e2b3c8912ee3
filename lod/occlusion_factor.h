// Neubert et al. 2011's view-dependent optimization (sec. 4): a tree mostly hidden by others needs
// fewer leaves. Its visible fraction f of sample points on its crown hull (lod/crown_samples.h),
// tested against the previous frame's depth buffer (lod/frame_depth.h), lowers the fraction of
// leaves kept, lambda_occl = lambda(d) * max(f, 0.1). Over frames f is smoothed so that a tree's
// level does not jump with every frame ("a hysteresis function", which the paper does not give):
// a rise is taken at once (a tree coming into view gets its leaves back without delay), a fall
// only a part of the way per frame.
#pragma once

#include <optional>
#include <vector>

#include "lod/crown_samples.h"
#include "lod/frame_depth.h"
#include "render/instance_transform.h"

namespace voltree {

struct OcclusionOptions {
  int samples = 64;          // sample points per tree on its crown hull
  double min_factor = 0.1;   // the paper's floor on f in lambda(d) * max(f, min_factor)
  double depth_bias = 0.05;  // of the tree's height: a point this far behind the depth still counts as seen
  double fall = 0.5;         // the part of a drop in f taken per frame (1: at once)
  // Throws OptionError naming the field.
  void Check() const;
};

// What the test saw of one tree.
struct Visibility {
  double fraction = 1;  // f: visible samples over tested ones; 1 when none was tested
  int tested = 0;       // the samples facing the frame's eye (the others face away from it)
};

// The samples (mesh frame) of an instance placed by `transform`, `height` tall in its mesh frame,
// tested against `depth`. Only the samples whose normal faces the depth frame's eye are tested:
// those facing away lie behind the tree's own crown from there.
Visibility VisibleFraction(const std::vector<CrownSample>& samples, const InstanceTransform& transform, double height,
                           const FrameDepth& depth, const OcclusionOptions& options);

// The smoothed f after a frame that measured `measured`, from the smoothed f before (none: the
// instance's first test).
double SmoothedVisibility(std::optional<double> previous, double measured, double fall);

// lambda(d) * max(f, min_factor), in (0, 1] for lambda in (0, 1].
double OccludedLambda(double lambda, double visible, double min_factor);

}  // namespace voltree
