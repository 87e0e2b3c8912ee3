// sRGB <-> CIELab (D65), the space in which billboard colours are quantized (Linz 2006, 4.1):
// L2 distances there follow perceived colour differences better than in sRGB.
// The formulas are those of OpenCV's cv::cvtColor(COLOR_RGB2Lab): sRGB transfer curve, D65 white
// (0.950456, 1, 1.088754), CIE 1976 with the 0.008856 / 7.787 linear segment.
#pragma once

#include <array>
#include <cstdint>

#include "core/srgb.h"

namespace voltree {

using Lab = std::array<float, 3>;  // L* in [0, 100], a* and b* roughly in [-128, 127]

// Float sRGB in [0, 1] -> Lab, like the CV_32F path of cvtColor.
Lab SrgbToLab(float r, float g, float b);
// 8-bit sRGB -> Lab (float, unscaled). Uses a 256-entry linearization table.
Lab Srgb8ToLab(uint8_t r, uint8_t g, uint8_t b);
// OpenCV's 8-bit Lab encoding: L * 255 / 100, a + 128, b + 128, rounded and saturated.
std::array<uint8_t, 3> EncodeLab8(const Lab& lab);

// Lab -> sRGB in [0, 1] (unclamped: out-of-gamut colours may leave [0, 1]).
std::array<float, 3> LabToSrgb(const Lab& lab);
// Lab -> 8-bit sRGB, clamped and rounded.
std::array<uint8_t, 3> LabToSrgb8(const Lab& lab);

}  // namespace voltree
