// The images of a side-by-side comparison in the report: truth and render composited over the
// evaluation's grey (what RGB PSNR and SSIM compare), and their amplified difference.
#pragma once

#include "core/image.h"

namespace voltree {

// RGB8 of an RGBA image over a grey background (8-bit units), rounded.
Image8 CompositeForDisplay(const Image8& rgba, float grey, bool premultiplied);

// |a - b| per channel times `gain`, clamped to 255: black where the images agree. Both RGB8 of
// the same size (Error otherwise).
Image8 AmplifiedDifference(const Image8& a, const Image8& b, float gain);

}  // namespace voltree
