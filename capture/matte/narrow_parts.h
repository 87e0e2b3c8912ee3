// Internal: the narrow parts of the visual hull as one photo sees it (a trunk, a bough). There
// the silhouettes of every photo agree closely, so the hull bounds the tree tightly and its
// centre line runs on the tree: what a matte leaves out there, it missed.
#pragma once

#include <opencv2/core.hpp>

#include "capture/matte/options.h"

namespace voltree::matte {

// Where the hull's projection `inside` (CV_8U, nonzero inside) is thinner than a disc of
// `radius` pixels; CV_8U, 255 there.
cv::Mat NarrowParts(const cv::Mat& inside, int radius);

// The centre lines of the narrow parts of `inside` (thinner than a disc of `radius` pixels), the
// slivers thinner than `band` along the crown's outline left out; CV_8U, 255 on them. Where the
// silhouettes of every photo agree that closely, the centre line runs on the tree.
cv::Mat NarrowCentreLines(const cv::Mat& inside, int radius, int band);

struct NarrowPartMend {
  int radius = 24;          // narrower than a disc of this radius (pixels) is a narrow part
  int band = 4;             // the hull's band (pixels): slivers thinner than this are no part
  double max_missed = 0.2;  // a part whose centre line the matte misses beyond this share is mended
  // Missed: at or below this 8-bit alpha, where the reconstruction carves (its carve_alpha 0.02).
  // A part the matte holds in part (a twig's mixed pixels) is not missed.
  int carve_alpha = 5;
};

// Solves `alpha` (CV_8U) again inside `region`: `tree` known tree and `background` (may be empty)
// known background there, the rest of the region decided by the solver from the photo's colours.
// Outside the region the matte is kept, and serves as the solver's context where it is sure.
void SolveAgainInside(const cv::Mat& rgb, const cv::Mat& region, const cv::Mat& tree, const cv::Mat& background,
                      const MatteOptions& options, cv::Mat& alpha);

// One eye-level photo of the aspen, matted from GrabCut's cut alone, took its grey trunk for the
// grey soil, and its matte alone then carved the trunk out of the volume in every view. Each
// narrow part whose centre line `alpha` (CV_8U) misses beyond `max_missed`, over at least twice
// `radius` pixels, is solved again: that centre line known tree, `background` (CV_8U, nonzero
// where known; may be empty) known background, the rest of the part by the solver from the
// photo's colours. The matte outside those parts is kept. Returns whether any part was mended.
// The length keeps the leafy end of a bough out: there the hull is loose, its centre line
// crosses the crown's gaps, and the matte rightly misses it (on the aspen: 25-32 pixels of such
// ends against 107 of the trunk, at a radius of 24).
bool MendMissedNarrowParts(const cv::Mat& rgb, const cv::Mat& inside, const cv::Mat& background,
                           const NarrowPartMend& mend, const MatteOptions& options, cv::Mat& alpha);

}  // namespace voltree::matte
