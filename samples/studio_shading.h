// The studio's light on the tree in GLSL, shared by the tree's shader and by whatever stands in
// for its leaves and bark (the LOD bench's points and lines), so both get the same colour at the
// same place.
#pragma once

namespace voltree {

// GLSL (no #version line) declaring the light's uniforms (uSunDirection, uSunColor, uSkyAmbient,
// uGroundAmbient, uCrownCenter, uCrownRadii) and
//   vec3 Shade(vec3 base, vec3 world, vec3 normal, bool double_sided)
// Self-shadowing of the crown without a shadow map: points deep inside the crown's ellipsoid and
// on its far side from the sun get less sun and less sky; a double-sided leaf lets light through.
inline constexpr const char* kStudioShadeGlsl = R"(
uniform vec3 uSunDirection;
uniform vec3 uSunColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
uniform vec3 uCrownCenter;
uniform vec3 uCrownRadii;

vec3 Shade(vec3 base, vec3 world, vec3 normal, bool double_sided) {
  vec3 q = (world - uCrownCenter) / uCrownRadii;
  float depth = clamp(length(q), 0.0, 1.0);
  float sunward = dot(q, uSunDirection);
  float sun_visibility = clamp(0.5 + 0.9 * sunward + 0.5 * (depth - 0.6), 0.12, 1.0);
  float sky_visibility = mix(0.35, 1.0, smoothstep(0.2, 1.0, depth));
  float n_dot_l = dot(normal, uSunDirection);
  float diffuse = max(n_dot_l, 0.0);
  if (double_sided) diffuse += 0.35 * max(-n_dot_l, 0.0);
  vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * normal.z) * sky_visibility;
  return base * (uSunColor * diffuse * sun_visibility + ambient);
}
)";

}  // namespace voltree
