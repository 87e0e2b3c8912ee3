// The last guard before an asset is written: the reconstruction must reproduce the mattes it was
// built from. The finest level's billboards of each input view, drawn there as the renderer
// draws them (reconstruct/billboard_raster.h) at a reduced size, against the matte averaged over
// the same pixel. A volume whose billboards cover what the mattes call empty, or miss what they
// call tree, is garbage whatever its later stages do. (The densities alone would be judged too
// harshly: a sparse crown at a coarse level has little optical depth where the photo is opaque.)
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/volume.h"

namespace voltree {

struct ReproductionOptions {
  int max_side = 128;            // each view is compared at most this large
  double covered_alpha = 0.5;    // alpha above which a pixel counts as covered
  double billboard_scale = 1.0;  // as reconstruct made the billboards
  // Limits on the mean over the views. Measured with the billboards: the demo's oak reproduces
  // its mattes at recall 0.994 and precision 0.999 (the error budget's billboards row), the
  // smallest set the tests run (young oak, 4 views at 32², 3 levels) at 0.67 and 0.92; a volume
  // built with the wrong bounds or from inconsistent mattes falls far below.
  double min_recall = 0.6;
  double min_precision = 0.5;
  void Check() const;  // throws Error naming the field
};

struct ViewReproduction {
  std::string name;
  double recall = 0;     // matte-covered pixels the volume covers
  double precision = 0;  // volume-covered pixels the matte covers
};

std::vector<ViewReproduction> MeasureReproduction(const Volume& volume, const std::vector<View>& views,
                                                  const std::vector<Image8>& mattes,
                                                  const ReproductionOptions& options);

// Throws Error when the mean recall or precision is below the limits, naming the worst views and
// what to try.
void CheckReproduction(const std::vector<ViewReproduction>& views, const ReproductionOptions& options);

}  // namespace voltree
