#include "samples/matte_scene.h"

#include <algorithm>
#include <cmath>

namespace voltree {

namespace {

// Deterministic hash noise in [0, 1).
float Hash(int x, int y, uint32_t seed) {
  uint32_t h = uint32_t(x) * 374761393u + uint32_t(y) * 668265263u + seed * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return float((h ^ (h >> 16)) & 0xffffff) / float(0x1000000);
}

// Bilinear value noise with `cell`-pixel cells.
float ValueNoise(float x, float y, float cell, uint32_t seed) {
  const float u = x / cell, v = y / cell;
  const int i = int(std::floor(u)), j = int(std::floor(v));
  const float fu = u - i, fv = v - j;
  const float a = Hash(i, j, seed), b = Hash(i + 1, j, seed), c = Hash(i, j + 1, seed), d = Hash(i + 1, j + 1, seed);
  return (a * (1 - fu) + b * fu) * (1 - fv) + (c * (1 - fu) + d * fu) * fv;
}

}  // namespace

MatteScene MakeMatteScene(int width, int height, uint32_t seed, float horizon) {
  MatteScene scene;
  scene.photo = Image8(width, height, 3);
  scene.alpha = Image8(width, height, 1);
  scene.foreground = Image8(width, height, 4);
  scene.horizon_row = int(horizon * height);
  const float cx = 0.5f * width, cy = 0.34f * height, rx = 0.3f * width, ry = 0.24f * height;
  const float trunk_half = 0.035f * width, trunk_bottom = 0.82f * height;
  auto to8 = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float px = x + 0.5f, py = y + 0.5f;
      // Background: sky gradient above the horizon, grass with dirt patches below.
      float bg[3];
      if (y < scene.horizon_row) {
        const float t = py / scene.horizon_row, s = px / width;
        bg[0] = 0.30f + 0.45f * t + 0.05f * s;
        bg[1] = 0.50f + 0.35f * t + 0.03f * s;
        bg[2] = 0.88f + 0.07f * t;
      } else {
        const float dirt = ValueNoise(px, py, 9.0f, seed + 7) > 0.6f ? 1.0f : 0.0f;
        const float grain = 0.16f * (Hash(x, y, seed + 3) - 0.5f);
        bg[0] = (dirt ? 0.50f : 0.32f) + grain;
        bg[1] = (dirt ? 0.40f : 0.48f) + grain;
        bg[2] = (dirt ? 0.28f : 0.20f) + grain;
      }
      // Crown: leaf coverage from noise, fading out at the ellipse edge.
      const float e = std::hypot((px - cx) / rx, (py - cy) / ry);
      const float leaves = ValueNoise(px, py, 3.0f, seed) * 0.6f + ValueNoise(px, py, 11.0f, seed + 1) * 0.4f;
      const float crown_alpha =
          std::clamp((leaves - 0.35f) * 4.0f, 0.0f, 1.0f) * std::clamp((1.0f - e) * 5.0f, 0.0f, 1.0f);
      const float shade = 0.7f + 0.5f * ValueNoise(px, py, 2.0f, seed + 2);
      const float crown[3] = {0.16f * shade, 0.36f * shade, 0.10f * shade};
      // Trunk: a vertical bar, antialiased at its sides and bottom.
      const float side = std::clamp(trunk_half - std::abs(px - cx) + 0.5f, 0.0f, 1.0f);
      const float trunk_alpha = py > cy ? side * std::clamp(trunk_bottom - py + 0.5f, 0.0f, 1.0f) : 0.0f;
      const float trunk[3] = {0.34f, 0.22f, 0.13f};
      // Crown over trunk, then over the background (premultiplied "over").
      const float alpha = crown_alpha + trunk_alpha * (1 - crown_alpha);
      float premultiplied[3];
      for (int c = 0; c < 3; ++c) {
        premultiplied[c] = crown_alpha * crown[c] + (1 - crown_alpha) * trunk_alpha * trunk[c];
        scene.photo.at(x, y, c) = to8(premultiplied[c] + (1 - alpha) * bg[c]);
        scene.foreground.at(x, y, c) = to8(premultiplied[c]);
      }
      scene.alpha.at(x, y) = to8(alpha);
      scene.foreground.at(x, y, 3) = to8(alpha);
    }
  return scene;
}

}  // namespace voltree
