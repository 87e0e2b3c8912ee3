#include "pipeline/comparison_images.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "core/image_metrics.h"

namespace voltree {

Image8 CompositeForDisplay(const Image8& rgba, float grey, bool premultiplied) {
  const ImageF composite = CompositeOverGrey(rgba, grey, premultiplied);
  Image8 out(composite.width, composite.height, 3);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = uint8_t(std::clamp(std::lround(composite.pixels[i]), 0L, 255L));
  return out;
}

Image8 AmplifiedDifference(const Image8& a, const Image8& b, float gain) {
  if (a.width != b.width || a.height != b.height || a.channels != 3 || b.channels != 3)
    Fail("difference image: expected two RGB images of one size, got ", a.width, "x", a.height, "x", a.channels,
         " and ", b.width, "x", b.height, "x", b.channels);
  Image8 out(a.width, a.height, 3);
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const float difference = std::abs(float(a.pixels[i]) - float(b.pixels[i])) * gain;
    out.pixels[i] = uint8_t(std::min(255.0f, std::round(difference)));
  }
  return out;
}

}  // namespace voltree
