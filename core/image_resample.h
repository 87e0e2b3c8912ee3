// Exact area averaging onto a coarser grid: each output pixel is the mean of the input area it
// covers, for any ratio (512 -> 320 as well as 512 -> 256). What a camera K times farther sees of
// a photo, and what the billboard fit compares a coarse level with.
#pragma once

#include "core/image.h"

namespace voltree {

// `in` resampled to width x height (each at most the input's); every channel alike, so colours
// must be premultiplied for alpha to weigh them.
ImageF AreaResample(const ImageF& in, int width, int height);

// 8-bit RGBA resampled as premultiplied colour; returned in the input's convention (straight in,
// straight out), rounded to nearest.
Image8 AreaResampleRgba(const Image8& rgba, bool premultiplied, int width, int height);

}  // namespace voltree
