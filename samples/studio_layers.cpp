#include "samples/studio_layers.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/srgb.h"
#include "samples/studio_lighting.h"

namespace voltree {
namespace {

uint8_t ToByte(float value) { return static_cast<uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

StudioLayers ComposeStudioLayers(const ImageF& tree, const ImageF& backdrop) {
  if (tree.width != backdrop.width || tree.height != backdrop.height || tree.channels != 4 || backdrop.channels < 3)
    Fail("studio: tree render ", tree.width, "x", tree.height, "x", tree.channels, " and backdrop ", backdrop.width,
         "x", backdrop.height, "x", backdrop.channels, " do not match");
  const int width = tree.width, height = tree.height;
  StudioLayers layers{Image8(width, height, 3), Image8(width, height, 4), Image8(width, height, 1),
                      Image8(width, height, 3)};
  // Every pixel is independent, so the parallel loop is deterministic.
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const uint8_t alpha = ToByte(tree.at(x, y, 3));
      layers.matte.at(x, y) = alpha;
      layers.foreground.at(x, y, 3) = alpha;
      const float coverage = std::clamp(tree.at(x, y, 3), 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) {
        uint8_t premultiplied = 0;
        if (alpha > 0) {
          const float straight = std::clamp(tree.at(x, y, c) / coverage, 0.0f, 1.0f);
          premultiplied = static_cast<uint8_t>(std::lround(LinearToSrgb(straight) * alpha));
        }
        const uint8_t behind = ToByte(LinearToSrgb(std::clamp(backdrop.at(x, y, c), 0.0f, 1.0f)));
        layers.foreground.at(x, y, c) = premultiplied;
        layers.background.at(x, y, c) = behind;
        layers.photo.at(x, y, c) = static_cast<uint8_t>(std::lround(premultiplied + (255 - alpha) * behind / 255.0f));
      }
    }
  });
  return layers;
}

}  // namespace voltree
