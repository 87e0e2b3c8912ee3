// A grid of thumbnails, to look at a set of photos at a glance.
#pragma once

#include <vector>

#include "core/image.h"

namespace voltree {

struct ContactSheetOptions {
  int columns = 6;
  int thumbnail_width = 192;  // thumbnails keep the images' aspect ratio
  int gap = 4;                // pixels between thumbnails
  uint8_t background = 32;    // grey level behind and between thumbnails
  void Check() const;
};

// Box-filtered thumbnails of `images` (RGB or RGBA; alpha is composited over the background),
// left to right, top to bottom. Returns an RGB image.
Image8 MakeContactSheet(const std::vector<Image8>& images, const ContactSheetOptions& options = {});

}  // namespace voltree
