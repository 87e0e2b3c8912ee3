// Foreground colour where alpha is fractional. A photo pixel is I = a F + (1 - a) B; with the
// background B filled in from the pure-background pixels around (smooth sky, blurred ground),
// the premultiplied foreground is a F = I - (1 - a) B, clamped to [0, a].
#pragma once

#include "core/image.h"

namespace voltree {

// `photo`: RGB (or RGBA, alpha ignored); `alpha`: 1 channel, same size. Returns premultiplied
// RGBA, alpha = `alpha`. Throws Error on size mismatch.
Image8 PremultipliedForeground(const Image8& photo, const Image8& alpha);

}  // namespace voltree
