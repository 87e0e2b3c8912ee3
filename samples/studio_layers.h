// Turns the studio's two linear renders into the 8-bit files of a workspace, so that exactly
//   photo = foreground + (1 - alpha) * background   (premultiplied over, on the stored sRGB values)
// up to rounding (half a level), and matte = foreground alpha bit for bit.
#pragma once

#include "core/image.h"

namespace voltree {

struct StudioLayers {
  Image8 photo;       // RGB, sRGB
  Image8 foreground;  // RGBA, sRGB colour premultiplied by alpha
  Image8 matte;       // grey, = foreground alpha
  Image8 background;  // RGB, sRGB: the backdrop alone
};

// `tree`: RGBA, linear colour premultiplied by coverage (alpha); `backdrop`: linear RGB(A), opaque.
// Same size. Colour above 1 clips.
StudioLayers ComposeStudioLayers(const ImageF& tree, const ImageF& backdrop);

}  // namespace voltree
