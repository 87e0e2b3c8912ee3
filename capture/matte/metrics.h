// Accuracy of an alpha matte against the true one, in the units alphamatting.com and the
// Composition-1k papers report:
//  SAD = sum |a - a*| / 1000, alpha in [0, 1] (so "thousands of fully wrong pixels");
//  MSE = mean (a - a*)^2 * 1000, alpha in [0, 1].
// alphamatting.com and Composition-1k take the MSE mean over the unknown region of their given
// trimap; we have no given trimap (ours is part of what is evaluated), so the mean runs over all
// pixels and `mse_band` repeats it over the pixels where either matte is fractional or they differ
// by more than 1/255, a stand-in for the unknown region.
#pragma once

#include "core/image.h"

namespace voltree {

struct MatteError {
  double sad = 0.0;       // thousands
  double mse = 0.0;       // x 1e3, over the whole image
  double mse_band = 0.0;  // x 1e3, over the "uncertain" pixels (0 when there are none)
  size_t band_pixels = 0;
};

// Both mattes 1-channel and the same size; throws Error otherwise.
MatteError CompareMattes(const Image8& estimate, const Image8& truth);

}  // namespace voltree
