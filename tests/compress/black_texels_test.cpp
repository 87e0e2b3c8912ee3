#include "compress/black_texels.h"

#include <gtest/gtest.h>

namespace voltree {
namespace {

TEST(BlackTexels, VisibleBlackTexelsTakeTheBrightestColour) {
  const int n = 4;  // 2x2 texels
  // Codeword 0: black, dark green, bright green, black. Codeword 1: all black.
  std::vector<uint8_t> rgb = {0, 0, 0, 20, 60, 10, 90, 200, 40, 2, 3, 1,  //
                              0, 0, 0, 0,  0,  0,  0,  0,   0,  0, 0, 0};
  // Alpha codeword 0 shows texels 0 and 1; codeword 1 shows texel 3.
  const std::vector<uint8_t> alpha = {255, 128, 0, 0, 0, 0, 0, 40};
  const std::vector<CodewordUse> uses = {{0, 0}, {0, 1}, {1, 1}};
  const size_t changed = FixBlackTexels(rgb, alpha, n, uses, 4);
  EXPECT_EQ(changed, 2u);
  const std::vector<uint8_t> expected = {90, 200, 40, 20, 60, 10, 90, 200, 40, 90, 200, 40,  //
                                         0,  0,   0,  0,  0,  0,  0,  0,   0,  0,  0,   0};
  EXPECT_EQ(rgb, expected);
}

TEST(BlackTexels, HiddenBlackTexelsStay) {
  std::vector<uint8_t> rgb = {0, 0, 0, 100, 100, 100};
  const std::vector<uint8_t> alpha = {0, 255};
  EXPECT_EQ(FixBlackTexels(rgb, alpha, 2, {{0, 0}}, 4), 0u);
  EXPECT_EQ(rgb[0], 0);
}

}  // namespace
}  // namespace voltree
