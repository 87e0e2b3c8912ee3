#include "compress/colour_space.h"

#include <algorithm>
#include <cmath>

namespace voltree {
namespace {

// D65 white point, as in OpenCV's colour conversions.
constexpr float kWhiteX = 0.950456f;
constexpr float kWhiteZ = 1.088754f;
constexpr float kEpsilon = 0.008856f;  // (6/29)^3 as rounded by the CIE and OpenCV
constexpr float kKappaSlope = 7.787f;  // slope of the linear segment of f(t)

float LabF(float t) { return t > kEpsilon ? std::cbrt(t) : kKappaSlope * t + 16.f / 116.f; }

float LabFInverse(float f) {
  const float cube = f * f * f;
  return cube > kEpsilon ? cube : (f - 16.f / 116.f) / kKappaSlope;
}

struct LinearTable {
  std::array<float, 256> values;
  LinearTable() {
    for (int i = 0; i < 256; ++i) values[i] = SrgbToLinear(i / 255.f);
  }
};

Lab LinearToLab(float r, float g, float b) {
  // sRGB primaries to XYZ (D65), normalized by the white point.
  const float x = (0.412453f * r + 0.357580f * g + 0.180423f * b) / kWhiteX;
  const float y = 0.212671f * r + 0.715160f * g + 0.072169f * b;
  const float z = (0.019334f * r + 0.119193f * g + 0.950227f * b) / kWhiteZ;
  const float fx = LabF(x), fy = LabF(y), fz = LabF(z);
  const float lightness = y > kEpsilon ? 116.f * fy - 16.f : 903.3f * y;
  return {lightness, 500.f * (fx - fy), 200.f * (fy - fz)};
}

uint8_t SaturateRound(float value) { return static_cast<uint8_t>(std::clamp(std::lround(value), 0L, 255L)); }

}  // namespace

Lab SrgbToLab(float r, float g, float b) { return LinearToLab(SrgbToLinear(r), SrgbToLinear(g), SrgbToLinear(b)); }

Lab Srgb8ToLab(uint8_t r, uint8_t g, uint8_t b) {
  static const LinearTable table;  // immutable after construction, thread-safe init
  return LinearToLab(table.values[r], table.values[g], table.values[b]);
}

std::array<uint8_t, 3> EncodeLab8(const Lab& lab) {
  return {SaturateRound(lab[0] * 255.f / 100.f), SaturateRound(lab[1] + 128.f), SaturateRound(lab[2] + 128.f)};
}

std::array<float, 3> LabToSrgb(const Lab& lab) {
  const float fy = (lab[0] + 16.f) / 116.f;
  const float fx = fy + lab[1] / 500.f;
  const float fz = fy - lab[2] / 200.f;
  // L* below 8 lies on the linear segment: Y = L / 903.3.
  const float y = lab[0] > 7.9996f ? fy * fy * fy : lab[0] / 903.3f;
  const float x = LabFInverse(fx) * kWhiteX;
  const float z = LabFInverse(fz) * kWhiteZ;
  const float r = 3.240479f * x - 1.537150f * y - 0.498535f * z;
  const float g = -0.969256f * x + 1.875991f * y + 0.041556f * z;
  const float b = 0.055648f * x - 0.204043f * y + 1.057311f * z;
  return {LinearToSrgb(std::max(r, 0.f)), LinearToSrgb(std::max(g, 0.f)), LinearToSrgb(std::max(b, 0.f))};
}

std::array<uint8_t, 3> LabToSrgb8(const Lab& lab) {
  const auto rgb = LabToSrgb(lab);
  return {SaturateRound(rgb[0] * 255.f), SaturateRound(rgb[1] * 255.f), SaturateRound(rgb[2] * 255.f)};
}

}  // namespace voltree
