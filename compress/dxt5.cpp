#include "compress/dxt5.h"

#include <squish.h>

#include "core/error.h"

namespace voltree {
namespace {

// RGB565 -> RGB888 by bit replication, as the S3TC specification and every decoder do.
void ExpandRgb565(uint16_t packed, int rgb[3]) {
  const int r = (packed >> 11) & 31, g = (packed >> 5) & 63, b = packed & 31;
  rgb[0] = (r << 3) | (r >> 2);
  rgb[1] = (g << 2) | (g >> 4);
  rgb[2] = (b << 3) | (b >> 2);
}

int FloorDiv256(int value) { return value >= 0 ? value / 256 : -((-value + 255) / 256); }

int InterpolateAlpha(int a0, int a1, int i, int steps, Dxt5Rounding rounding) {
  switch (rounding) {
    case Dxt5Rounding::kTruncate:
      return ((steps - i) * a0 + i * a1) / steps;
    case Dxt5Rounding::kLlvmpipe: {
      const int weight = (i * (255 * 64 / steps)) >> 6;
      const int step = (a1 - a0) * weight;
      return a0 + FloorDiv256(step);
    }
    case Dxt5Rounding::kNearest:
    default:
      return ((steps - i) * a0 + i * a1 + steps / 2) / steps;
  }
}

void DecodeAlpha(const uint8_t* block, uint8_t* rgba, Dxt5Rounding rounding) {
  const int a0 = block[0], a1 = block[1];
  int palette[8] = {a0, a1};
  if (a0 > a1) {
    for (int i = 1; i <= 6; ++i) palette[i + 1] = InterpolateAlpha(a0, a1, i, 7, rounding);
  } else {
    for (int i = 1; i <= 4; ++i) palette[i + 1] = InterpolateAlpha(a0, a1, i, 5, rounding);
    palette[6] = 0;
    palette[7] = 255;
  }
  uint64_t bits = 0;  // 48 bits of 3-bit indices, little-endian
  for (int i = 0; i < 6; ++i) bits |= uint64_t(block[2 + i]) << (8 * i);
  for (int t = 0; t < 16; ++t) rgba[4 * t + 3] = static_cast<uint8_t>(palette[(bits >> (3 * t)) & 7]);
}

void DecodeColour(const uint8_t* block, uint8_t* rgba, Dxt5Rounding rounding) {
  int c[4][3];
  ExpandRgb565(uint16_t(block[0] | block[1] << 8), c[0]);
  ExpandRgb565(uint16_t(block[2] | block[3] << 8), c[1]);
  for (int ch = 0; ch < 3; ++ch) {              // DXT3/5 colour blocks are always in 4-colour mode
    if (rounding == Dxt5Rounding::kLlvmpipe) {  // 8-bit fixed-point weights 85/256 and 170/256
      c[2][ch] = c[0][ch] + FloorDiv256((c[1][ch] - c[0][ch]) * 85);
      c[3][ch] = c[0][ch] + FloorDiv256((c[1][ch] - c[0][ch]) * 170);
    } else {
      c[2][ch] = (2 * c[0][ch] + c[1][ch]) / 3;
      c[3][ch] = (c[0][ch] + 2 * c[1][ch]) / 3;
    }
  }
  const uint32_t bits = block[4] | block[5] << 8 | block[6] << 16 | uint32_t(block[7]) << 24;
  for (int t = 0; t < 16; ++t) {
    const int index = (bits >> (2 * t)) & 3;
    for (int ch = 0; ch < 3; ++ch) rgba[4 * t + ch] = static_cast<uint8_t>(c[index][ch]);
  }
}

}  // namespace

std::vector<uint8_t> EncodeDxt5(const uint8_t* rgba, int width, int height) {
  if (width <= 0 || height <= 0 || width % 4 || height % 4)
    Fail("DXT5: image size ", width, "x", height, " is not a positive multiple of 4");
  const int flags = squish::kDxt5 | squish::kColourClusterFit;
  std::vector<uint8_t> blocks(static_cast<size_t>(squish::GetStorageRequirements(width, height, flags)));
  squish::CompressImage(rgba, width, height, blocks.data(), flags);
  return blocks;
}

void DecodeDxt5Block(const uint8_t* block, uint8_t* rgba, Dxt5Rounding rounding) {
  DecodeAlpha(block, rgba, rounding);
  DecodeColour(block + 8, rgba, rounding);
}

std::vector<uint8_t> DecodeDxt5(const uint8_t* blocks, int width, int height, Dxt5Rounding rounding) {
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  const int blocks_x = width / 4;
  for (int by = 0; by < height / 4; ++by) {
    for (int bx = 0; bx < blocks_x; ++bx) {
      uint8_t texels[64];
      DecodeDxt5Block(blocks + size_t(by * blocks_x + bx) * kDxt5BlockBytes, texels, rounding);
      for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
          for (int ch = 0; ch < 4; ++ch)
            rgba[(size_t(by * 4 + y) * width + bx * 4 + x) * 4 + ch] = texels[(y * 4 + x) * 4 + ch];
    }
  }
  return rgba;
}

}  // namespace voltree
