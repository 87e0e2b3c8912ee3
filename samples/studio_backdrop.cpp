#include "samples/studio_backdrop.h"

#include <string>

#include "render/gl_context.h"
#include "samples/studio_projection.h"

namespace voltree {
namespace {

constexpr const char* kFragmentMain = R"(
out vec4 outColor;
uniform float uSupersample;
uniform float uTargetHeight;     // rows of the supersampled target
uniform float uSampleAngle;      // radians per supersample, for filtering detail
uniform uvec2 uSeed;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;
uniform vec3 uSkyZenith;
uniform vec3 uSkyHorizon;
uniform vec3 uSkyAmbient;
uniform float uHazeDistance;

uvec3 Pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return v;
}

// Three independent uniform values in [0, 1) for an integer lattice cell and a layer.
vec3 Hash3(ivec2 cell, uint layer) {
  uvec3 h = Pcg3d(uvec3(uvec2(cell) ^ uSeed, layer * 2654435761u ^ uSeed.x));
  return vec3(h >> 8u) * (1.0 / 16777216.0);
}

float ValueNoise(vec2 p, uint layer) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 u = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(i);
  float a = Hash3(c, layer).x, b = Hash3(c + ivec2(1, 0), layer).x;
  float d = Hash3(c + ivec2(0, 1), layer).x, e = Hash3(c + ivec2(1, 1), layer).x;
  return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// Octaves whose period is below about two samples fade to their mean instead of aliasing.
float Fbm(vec2 p, uint layer, int octaves, float footprint) {
  float sum = 0.0, amplitude = 0.5, frequency = 1.0, total = 0.0;
  for (int o = 0; o < octaves; ++o) {
    float keep = 1.0 - smoothstep(0.25, 0.5, frequency * footprint);
    sum += amplitude * mix(0.5, ValueNoise(p * frequency, layer + uint(o)), keep);
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.03;
  }
  return sum / total;
}

// Stones: at most one per cell of 0.8 m, round, with a shaded rim. Returns (coverage, shade).
// Stones smaller than a few samples fade out instead of flickering.
vec2 Stones(vec2 p, float footprint) {
  const float kCell = 0.8;
  vec2 q = p / kCell;
  ivec2 base = ivec2(floor(q));
  vec2 best = vec2(0.0, 1.0);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 cell = base + ivec2(dx, dy);
      vec3 h = Hash3(cell, 101u);
      if (h.z < 0.45) continue;
      float radius = mix(0.06, 0.3, fract(h.z * 7.31));
      vec2 center = vec2(cell) + 0.2 + 0.6 * h.xy;
      float d = length(q - center) / radius;
      float size_in_samples = kCell * radius / max(footprint, 1e-6);
      float edge = 1.0 / max(size_in_samples, 1.0);
      float coverage = (1.0 - smoothstep(1.0 - edge, 1.0 + edge, d)) * smoothstep(1.0, 3.0, size_in_samples);
      float shade = mix(0.5, 1.4, fract(h.x * 13.7)) * (1.0 - 0.5 * min(d * d, 1.0));
      if (coverage > best.x) best = vec2(coverage, shade);
    }
  return best;
}

vec3 GroundAlbedo(vec2 p, float footprint) {
  float patches = Fbm(p * 0.12, 1u, 4, footprint * 0.12);
  float grassiness = smoothstep(0.42, 0.58, patches);
  float blades = Fbm(p * 18.0, 10u, 3, footprint * 18.0);
  float tufts = Fbm(p * 2.5, 20u, 3, footprint * 2.5);
  // Dark clumps and light dry spots half a metre across: blobs that feature detectors like.
  float clumps = Fbm(p * 1.1, 25u, 3, footprint * 1.1);
  float clump_shade = mix(0.45, 1.45, smoothstep(0.3, 0.7, clumps));
  vec3 grass = mix(vec3(0.035, 0.075, 0.015), vec3(0.13, 0.20, 0.04), tufts) * (0.55 + 0.9 * blades) * clump_shade;
  float grain = Fbm(p * 9.0, 30u, 3, footprint * 9.0);
  float clods = Fbm(p * 1.3, 40u, 3, footprint * 1.3);
  vec3 soil = mix(vec3(0.09, 0.06, 0.035), vec3(0.26, 0.19, 0.11), clods) * (0.6 + 0.8 * grain);
  vec3 albedo = mix(soil, grass, grassiness);
  vec2 stone = Stones(p, footprint);
  vec3 rock = vec3(0.22, 0.21, 0.19) * stone.y * (0.8 + 0.4 * grain);
  return mix(albedo, rock, stone.x);
}

vec3 Sky(vec3 direction) {
  float up = max(direction.z, 0.0);
  vec3 sky = mix(uSkyHorizon, uSkyZenith, pow(up, 0.6));
  float sun = max(dot(direction, uSunDirection), 0.0);
  sky += uSunColor * (0.04 * pow(sun, 12.0) + 0.25 * pow(sun, 400.0));
  // Clouds on a plane above the camera, fading into the haze at the horizon.
  vec2 cloud_uv = direction.xy / max(direction.z, 0.03) * 0.6;
  float footprint = uSampleAngle / max(direction.z, 0.03);
  float density = Fbm(cloud_uv, 60u, 6, footprint * 0.6);
  float cover = smoothstep(0.48, 0.72, density) * smoothstep(0.0, 0.2, direction.z);
  vec3 cloud = vec3(0.85, 0.86, 0.9) * (0.75 + 0.35 * density);
  return mix(sky, cloud, cover * 0.85);
}

void main() {
  vec2 pixel = vec2(gl_FragCoord.x, uTargetHeight - gl_FragCoord.y) / uSupersample;
  vec3 direction = PixelRay(pixel);
  vec3 eye = CameraCenter();
  vec3 color;
  if (direction.z < -1e-4 && eye.z > 0.0) {
    float t = -eye.z / direction.z;
    vec2 p = eye.xy + t * direction.xy;
    // Metres per sample on the ground: the geometric mean of its across and along extents.
    float footprint = t * uSampleAngle / sqrt(max(-direction.z, 1e-3));
    vec3 albedo = GroundAlbedo(p, footprint);
    vec3 lit = albedo * (uSunColor * max(uSunDirection.z, 0.0) + uSkyAmbient);
    color = mix(lit, uSkyHorizon, 1.0 - exp(-t / uHazeDistance));
  } else {
    color = Sky(direction);
  }
  outColor = vec4(max(color, vec3(0.0)), 1.0);
}
)";

}  // namespace

StudioBackdrop::StudioBackdrop(uint64_t seed, double scene_size) : seed_(seed), scene_size_(scene_size) {
  program_ = ShaderProgram::Graphics("studio backdrop", kFullScreenTriangleVertexShader,
                                     std::string("#version 430 core\n") + kStudioProjectionGlsl + kFragmentMain);
}

void StudioBackdrop::Draw(const View& view, const StudioLighting& lighting, int supersample) const {
  SetStudioCamera(program_, view, 0.1, 1.0);  // depth is unused
  const GLuint seed_low = static_cast<GLuint>(seed_ & 0xFFFFFFFFu), seed_high = static_cast<GLuint>(seed_ >> 32);
  glProgramUniform2ui(program_.id(), program_.Location("uSeed"), seed_low * 747796405u + 2891336453u,
                      seed_high ^ 0x9E3779B9u);
  program_.Set("uSupersample", static_cast<float>(supersample));
  program_.Set("uTargetHeight", static_cast<float>(view.camera.height * supersample));
  program_.Set("uSampleAngle", static_cast<float>(1.0 / (view.camera.FocalX() * supersample)));
  program_.Set("uSunDirection", lighting.sun_direction);
  program_.Set("uSunColor", lighting.sun_color);
  program_.Set("uSkyZenith", lighting.sky_zenith);
  program_.Set("uSkyHorizon", lighting.sky_horizon);
  program_.Set("uSkyAmbient", lighting.sky_ambient);
  program_.Set("uHazeDistance", static_cast<float>(std::max(40.0 * scene_size_, 50.0)));
  program_.Use();
  empty_vertex_array_.Bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  CheckGl("drawing the backdrop");
}

}  // namespace voltree
