// DXT5 (BC3) blocks: 16 bytes per 4x4 texels; 8 bytes of alpha (two 8-bit endpoints + 3-bit
// indices) then 8 bytes of colour (two RGB565 endpoints + 2-bit indices, always 4-colour mode).
// Encoding goes through libsquish with cluster fit; decoding is our own reference, which tests
// compare with libsquish and with the GL driver.
#pragma once

#include <cstdint>
#include <vector>

namespace voltree {

constexpr int kDxt5BlockBytes = 16;

// Encodes an RGBA8 image (width and height multiples of 4) into row-major DXT5 blocks.
std::vector<uint8_t> EncodeDxt5(const uint8_t* rgba, int width, int height);

// Decoders differ in how they round the interpolants, which the S3TC specification defines as
// real numbers (differences of at most 1).
enum class Dxt5Rounding {
  kNearest,   // alpha rounded to nearest, colour truncated (2c0 + c1) / 3: used for measurements
  kTruncate,  // libsquish's squish::Decompress: both truncated
  kLlvmpipe,  // Mesa llvmpipe (gallivm), measured bit-exact: v0 + floor((v1 - v0) * w / 256) with
              // colour w = 85, 170 and alpha w = floor(i * floor(255 * 64 / 7) / 64) (or / 5)
};

// Decodes one block into 16 RGBA8 texels, row-major.
void DecodeDxt5Block(const uint8_t* block, uint8_t* rgba, Dxt5Rounding rounding = Dxt5Rounding::kNearest);

// Decodes a whole image of row-major blocks into RGBA8.
std::vector<uint8_t> DecodeDxt5(const uint8_t* blocks, int width, int height,
                                Dxt5Rounding rounding = Dxt5Rounding::kNearest);

}  // namespace voltree
