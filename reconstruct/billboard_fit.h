// Billboards fitted to the photos.
//
// The tomography's billboards reproduce the mattes only roughly: texel alphas follow from the
// densities through the responsibility rule, colours are box averages, and neither knows how the
// renderer filters and composites them. The fit closes that gap. At an input view the renderer
// draws that view's billboards alone (its blend weight is 1), so each (level, view) pair is an
// independent problem: find the view's premultiplied RGBA texels, bounded to 0 <= rgb <= a <= 1,
// that minimise
//   sum over pixels |composite - photo|^2 (RGB and alpha, premultiplied)
//     + prior * sum over texel channels |texel - tomography texel|^2
// where the composite is the renderer's own image formation (billboard_raster.h: back-to-front
// order, plane intersection, bilinear taps). The prior keeps what the photo cannot decide (how
// alpha is shared between cells along a ray) where the tomography put it, which is what held-out
// views need. Each level is fitted against the photo box-filtered to that level's scale (one of
// its texels per pixel), so a level looks right at the distance the renderer draws it.
//
// Solver: projected, diagonally preconditioned Gauss-Newton steps (the diagonal of J^T J, which
// the backward pass gets for free) with backtracking, so the loss never rises. Held-out views
// are never used. Jobs run in parallel over (level, view); each is sequential, so the result does
// not depend on the thread count.
#pragma once

#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/progress.h"
#include "core/volume.h"

namespace voltree {

struct BillboardFitOptions {
  bool enabled = true;
  int iterations = 24;        // Gauss-Newton steps per (level, view)
  double prior = 0.05;        // weight of a texel channel's change against one pixel channel's error
  double alpha_weight = 2.0;  // weight of the matte's error against one colour channel's
  // The view's billboards are also drawn, blended, at cameras between it and its neighbours: fit
  // them to the nearest input photos too, as seen from there, so that blending two views agrees.
  int neighbours = 2;
  double neighbour_weight = 0.5;
  double billboard_scale = 1.0;
  void Check() const;  // throws Error naming the field
};

// Errors at the input views, at each level's fitting scale, before and after.
struct BillboardFitLevel {
  int level = 0;
  double scale = 0;                                    // photo pixels per fitted pixel (mean over views)
  size_t layers = 0;                                   // billboard layers over all views' pixels
  double rgb_psnr_before = 0, rgb_psnr_after = 0;      // premultiplied RGB, dB
  double alpha_psnr_before = 0, alpha_psnr_after = 0;  // dB
  double loss_before = 0, loss_after = 0;              // the objective, summed over views
};

struct BillboardFitReport {
  std::vector<BillboardFitLevel> levels;
  std::vector<std::string> warnings;  // jobs that diverged and kept their unfitted texels
  double seconds = 0;
};

// Fits every level's billboards of `volume` (made by MakeBillboards from these views, mattes
// and premultiplied RGBA foregrounds) in place.
BillboardFitReport FitBillboards(const std::vector<View>& views, const std::vector<Image8>& mattes,
                                 const std::vector<Image8>& foreground, const BillboardFitOptions& options,
                                 Volume* volume, Progress* progress);

}  // namespace voltree
