#include "compress/black_texels.h"

#include <algorithm>

namespace voltree {

size_t FixBlackTexels(std::vector<uint8_t>& rgb, const std::vector<uint8_t>& alpha, int texel_count,
                      const std::vector<CodewordUse>& uses, int black_threshold) {
  const size_t colour_count = rgb.size() / (3 * size_t(texel_count));
  // visible[i * n + t]: some billboard shows texel t of colour codeword i with alpha > 0.
  std::vector<uint8_t> visible(colour_count * texel_count, 0);
  for (const CodewordUse& use : uses) {
    const uint8_t* a = alpha.data() + size_t(use.alpha) * texel_count;
    for (int t = 0; t < texel_count; ++t)
      if (a[t] > 0) visible[size_t(use.colour) * texel_count + t] = 1;
  }
  auto is_black = [&](const uint8_t* c) {
    return c[0] <= black_threshold && c[1] <= black_threshold && c[2] <= black_threshold;
  };
  size_t changed = 0;
  for (size_t i = 0; i < colour_count; ++i) {
    uint8_t* word = rgb.data() + i * 3 * texel_count;
    int brightest = -1, brightest_sum = -1;
    for (int t = 0; t < texel_count; ++t) {
      const uint8_t* c = word + 3 * t;
      const int sum = c[0] + c[1] + c[2];
      if (!is_black(c) && sum > brightest_sum) brightest = t, brightest_sum = sum;
    }
    if (brightest < 0) continue;  // an all-black codeword is taken to be truly black
    for (int t = 0; t < texel_count; ++t) {
      if (visible[i * texel_count + t] && is_black(word + 3 * t)) {
        std::copy_n(word + 3 * brightest, 3, word + 3 * t);
        ++changed;
      }
    }
  }
  return changed;
}

}  // namespace voltree
