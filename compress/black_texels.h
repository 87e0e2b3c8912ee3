// Linz 2006, 4.1.1: colour and alpha are quantized apart, so a visible texel (alpha > 0) may get a
// black colour from its colour codeword and render as a dark speck. Since codewords are shared
// through the atlas, the fix is applied to the codewords: a black texel of colour codeword i that
// some billboard using i shows with non-zero alpha gets the brightest colour of that codeword.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voltree {

struct CodewordUse {
  uint16_t colour = 0;
  uint16_t alpha = 0;
};

// `rgb`: K x texel_count x 3 straight sRGB; `alpha`: K_a x texel_count. A texel is black when
// all of its channels are <= `black_threshold`. Returns the number of texels changed.
size_t FixBlackTexels(std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texel_count,
                      const std::vector<CodewordUse>& uses, int black_threshold);

}  // namespace voltree
