#include "core/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace voltree {

void ContactSheetOptions::Check() const {
  if (columns < 1) Fail("contact sheet: columns must be at least 1, got ", columns);
  if (thumbnail_width < 8) Fail("contact sheet: thumbnail width must be at least 8, got ", thumbnail_width);
  if (gap < 0) Fail("contact sheet: gap must not be negative");
}

namespace {

// Averages the source pixels under each thumbnail pixel, compositing alpha over `background`.
void DrawThumbnail(const Image8& source, int width, int height, uint8_t background, Image8& sheet, int left, int top) {
  for (int y = 0; y < height; ++y) {
    const int y0 = y * source.height / height, y1 = std::max(y0 + 1, (y + 1) * source.height / height);
    for (int x = 0; x < width; ++x) {
      const int x0 = x * source.width / width, x1 = std::max(x0 + 1, (x + 1) * source.width / width);
      double sum[3] = {0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx) {
          const double alpha = source.channels == 4 ? source.at(sx, sy, 3) / 255.0 : 1.0;
          for (int c = 0; c < 3; ++c) {
            const double value = source.at(sx, sy, source.channels >= 3 ? c : 0);
            sum[c] += alpha * value + (1 - alpha) * background;
          }
        }
      const double count = double(x1 - x0) * (y1 - y0);
      for (int c = 0; c < 3; ++c) sheet.at(left + x, top + y, c) = uint8_t(std::lround(sum[c] / count));
    }
  }
}

}  // namespace

Image8 MakeContactSheet(const std::vector<Image8>& images, const ContactSheetOptions& options) {
  options.Check();
  if (images.empty()) Fail("contact sheet: no images");
  const int width = options.thumbnail_width;
  const int height = std::max(1, width * images[0].height / std::max(1, images[0].width));
  const int columns = std::min<int>(options.columns, images.size());
  const int rows = (static_cast<int>(images.size()) + columns - 1) / columns;
  Image8 sheet(options.gap + columns * (width + options.gap), options.gap + rows * (height + options.gap), 3,
               options.background);
  for (size_t i = 0; i < images.size(); ++i) {
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    DrawThumbnail(images[i], width, height, options.background, sheet, options.gap + column * (width + options.gap),
                  options.gap + row * (height + options.gap));
  }
  return sheet;
}

}  // namespace voltree
