// The last guard before an asset is written: the reconstruction must reproduce the mattes it was
// built from. Rays through the finest level's densities, one per pixel of each input view at a
// reduced size, against the matte averaged over the same pixel. A volume that covers what the
// mattes call empty, or misses what they call tree, is garbage whatever its later stages do.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "reconstruct/volume.h"

namespace voltree {

struct ReproductionOptions {
  int max_side = 128;          // each view is compared at most this large
  double covered_alpha = 0.5;  // alpha above which a pixel counts as covered
  // Limits on the mean over the views. Measured on studio sets (true and automatic mattes, oak,
  // pine, young oak): recall >= 0.9 and precision >= 0.85; a volume built with the wrong bounds
  // or from inconsistent mattes falls far below.
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
