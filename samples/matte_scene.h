// A synthetic photo for measuring matting: blue sky gradient, textured ground below a horizon, a
// noisy green crown with fractional alpha and a brown trunk that crosses the horizon. Everything
// is composited from known layers, so the true alpha and premultiplied foreground are exact.
#pragma once

#include <cstdint>

#include "core/image.h"

namespace voltree {

struct MatteScene {
  Image8 photo;       // RGB
  Image8 alpha;       // true matte
  Image8 foreground;  // true premultiplied RGBA
  int horizon_row = 0;
};

// `horizon` is the horizon row as a fraction of the height; 0 photographs the tree against ground
// only (a camera looking down).
MatteScene MakeMatteScene(int width, int height, uint32_t seed = 1, float horizon = 0.62f);

}  // namespace voltree
