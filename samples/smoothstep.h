// GLSL's smoothstep on the CPU, for procedural bark, leaves and branch profiles.
#pragma once

#include <algorithm>

namespace voltree {

// 0 below lo, 1 above hi, a cubic Hermite ramp between.
inline float Smoothstep(float lo, float hi, float x) {
  const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace voltree
