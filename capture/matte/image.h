// Automatic alpha matting of one photo of a tree against sky and ground (see matte_trimap.h for
// the method, matte_options.h for its settings).
#pragma once

#include "capture/matte/options.h"
#include "core/image.h"

namespace voltree {

struct MatteResult {
  Image8 alpha;       // 1 channel
  Image8 foreground;  // RGBA, premultiplied colour
  Image8 trimap;      // 1 channel, 0 / 128 / 255 (for inspection and tests)
  int horizon_row = 0;
};

// `photo`: RGB or RGBA 8-bit sRGB (alpha ignored). Deterministic. `options` must pass Check().
MatteResult MatteImage(const Image8& photo, const MatteOptions& options);

}  // namespace voltree
