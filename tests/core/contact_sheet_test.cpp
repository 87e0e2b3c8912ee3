#include "core/contact_sheet.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace voltree {
namespace {

TEST(ContactSheet, LaysOutThumbnailsInRowsWithGaps) {
  std::vector<Image8> images;
  for (int i = 0; i < 5; ++i) images.emplace_back(40, 20, 3, uint8_t(40 * i));
  ContactSheetOptions options;
  options.columns = 3;
  options.thumbnail_width = 10;
  options.gap = 2;
  const Image8 sheet = MakeContactSheet(images, options);
  EXPECT_EQ(sheet.width, 2 + 3 * 12);
  EXPECT_EQ(sheet.height, 2 + 2 * 7);          // thumbnails are 10x5
  EXPECT_EQ(sheet.at(2, 2, 0), 0);             // first thumbnail
  EXPECT_EQ(sheet.at(2 + 12 + 5, 4, 1), 40);   // second, middle
  EXPECT_EQ(sheet.at(2 + 12, 2 + 7, 2), 160);  // fifth: second row, second column
  EXPECT_EQ(sheet.at(0, 0, 0), options.background);
  EXPECT_EQ(sheet.at(2 + 24 + 3, 2 + 7 + 2, 0), options.background);  // empty sixth slot
}

TEST(ContactSheet, AveragesAndCompositesAlphaOverBackground) {
  Image8 rgba(4, 4, 4, 0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 2; ++x) {  // left half opaque white, right half transparent
      for (int c = 0; c < 4; ++c) rgba.at(x, y, c) = 255;
    }
  ContactSheetOptions options;
  options.thumbnail_width = 8;  // thumbnails may not be larger than needed, but must not crash
  options.gap = 0;
  options.background = 0;
  const Image8 big = MakeContactSheet({rgba}, options);
  EXPECT_EQ(big.at(0, 0, 0), 255);
  EXPECT_EQ(big.at(7, 0, 0), 0);
  options.thumbnail_width = 8;
  Image8 wide(16, 16, 4, 0);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; x += 2) wide.at(x, y, 0) = wide.at(x, y, 3) = 255;
  const Image8 halved = MakeContactSheet({wide}, options);
  EXPECT_EQ(halved.at(3, 3, 0), 128);  // half the texels are red and opaque
  EXPECT_EQ(halved.at(3, 3, 1), 0);
}

TEST(ContactSheet, RejectsBadOptionsAndNoImages) {
  EXPECT_THROW(MakeContactSheet({}), Error);
  ContactSheetOptions options;
  options.columns = 0;
  EXPECT_THROW(MakeContactSheet({Image8(4, 4, 3)}, options), Error);
}

}  // namespace
}  // namespace voltree
