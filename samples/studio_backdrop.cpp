#include "samples/studio_backdrop.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

#include "render/gl_context.h"
#include "samples/studio_projection.h"

namespace voltree {
namespace {

constexpr size_t kMaxClutterObjects = 80;  // kMaxObjects in the shader

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
// The realistic backdrop (uRealistic = 1): objects on the ground around the camera ring and a
// distant skyline on a cylinder around the tree. Plain (0): sky and ground only.
const int kMaxObjects = 80;
uniform int uRealistic;
uniform int uObjectCount;
uniform vec4 uObjectShape[kMaxObjects];  // centre x, y, z, horizontal radius
uniform vec4 uObjectKind[kMaxObjects];   // kind (0 bush, 1 rock, 2 tree), vertical radius, trunk radius, tint
uniform vec2 uCenter;                    // the tree's position on the ground
uniform float uWallRadius;               // distance of the skyline

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


// Ray parameter where the ray enters the ellipsoid (centre c, radii r), or -1.
float HitEllipsoid(vec3 origin, vec3 direction, vec3 c, vec3 r) {
  vec3 o = (origin - c) / r, d = direction / r;
  float a = dot(d, d), b = dot(o, d), k = dot(o, o) - 1.0;
  float disc = b * b - a * k;
  if (disc < 0.0) return -1.0;
  float t = (-b - sqrt(disc)) / a;
  return t > 0.0 ? t : -1.0;
}

// Ray parameter where the ray meets the vertical cylinder (axis through c.xy, radius r, z in
// [0, top]) from outside, or -1.
float HitTrunk(vec3 origin, vec3 direction, vec2 c, float r, float top) {
  vec2 o = origin.xy - c, d = direction.xy;
  float a = dot(d, d), b = dot(o, d), k = dot(o, o) - r * r;
  float disc = b * b - a * k;
  if (a < 1e-12 || disc < 0.0) return -1.0;
  float t = (-b - sqrt(disc)) / a;
  float z = origin.z + t * direction.z;
  return (t > 0.0 && z >= 0.0 && z <= top) ? t : -1.0;
}

vec3 Lit(vec3 albedo, vec3 normal) {
  float sun = max(dot(normal, uSunDirection), 0.0);
  return albedo * (uSunColor * sun + uSkyAmbient * (0.6 + 0.4 * normal.z));
}

// The nearest object along the ray: (t, colour); t < 0 when none. Intersections first, then
// the one texture lookup of the nearest.
vec4 Objects(vec3 eye, vec3 direction) {
  float best = 1e30;
  int hit = -1;
  bool trunk = false;
  for (int i = 0; i < uObjectCount; ++i) {
    vec4 shape = uObjectShape[i], kind = uObjectKind[i];
    float t = HitEllipsoid(eye, direction, shape.xyz, vec3(shape.w, shape.w, kind.y));
    if (t > 0.0 && t < best) { best = t; hit = i; trunk = false; }
    if (kind.x > 1.5) {  // a tree: crown on a trunk
      float tt = HitTrunk(eye, direction, shape.xy, kind.z, shape.z);
      if (tt > 0.0 && tt < best) { best = tt; hit = i; trunk = true; }
    }
  }
  if (hit < 0) return vec4(0.0, 0.0, 0.0, -1.0);
  vec4 shape = uObjectShape[hit], kind = uObjectKind[hit];
  vec3 radii = vec3(shape.w, shape.w, kind.y);
  vec3 p = eye + best * direction;
  vec3 local = p - shape.xyz;
  float footprint = best * uSampleAngle;
  vec3 color;
  if (trunk) {
    vec3 n = normalize(vec3(p.xy - shape.xy, 0.0));
    float bark = Fbm(vec2(atan(n.y, n.x) * kind.z * 8.0, p.z * 3.0), 80u, 3, footprint * 8.0);
    color = Lit(vec3(0.10, 0.07, 0.045) * (0.6 + 0.8 * bark), n);
  } else {
    vec3 n = normalize(local / (radii * radii));
    vec2 uv = vec2(atan(local.y, local.x) * shape.w, local.z);
    if (kind.x < 0.5 || kind.x > 1.5) {  // leaves: clumps, gaps and a tint per object
      float scale = kind.x < 0.5 ? 5.0 : 2.5;
      float clumps = Fbm(uv * scale, 90u + uint(kind.w * 7.0), 4, footprint * scale);
      float leaves = Fbm(uv * scale * 6.0, 95u, 2, footprint * scale * 6.0);
      vec3 green = mix(vec3(0.03, 0.07, 0.02), vec3(0.12, 0.17, 0.05), kind.w);
      float shade = mix(0.35, 1.5, smoothstep(0.3, 0.7, clumps)) * (0.7 + 0.6 * leaves);
      color = Lit(green * shade, n) * (0.55 + 0.45 * smoothstep(-1.0, 0.6, n.z));
    } else {  // rock: grey, grained and lichened
      float grain = Fbm(uv * 6.0, 110u, 4, footprint * 6.0);
      float lichen = smoothstep(0.55, 0.7, Fbm(uv * 2.0, 115u, 2, footprint * 2.0));
      vec3 stone = mix(vec3(0.20, 0.19, 0.17), vec3(0.34, 0.32, 0.28), kind.w) * (0.6 + 0.8 * grain);
      color = Lit(mix(stone, vec3(0.20, 0.22, 0.10), lichen * 0.6), n);
    }
  }
  return vec4(color, best);
}

// The skyline on a cylinder of radius uWallRadius around the tree: hills, a tree line in
// patches, and buildings between them. Returns (colour, 1) where the ray meets it below the
// skyline, (0, 0) above; `t` is where the ray meets the cylinder (WallDistance).
float WallDistance(vec3 eye, vec3 direction) {
  vec2 o = eye.xy - uCenter, d = direction.xy;
  float a = dot(d, d), b = dot(o, d), k = dot(o, o) - uWallRadius * uWallRadius;
  return a > 1e-12 ? (-b + sqrt(max(b * b - a * k, 0.0))) / a : 1e30;
}

vec4 Skyline(vec3 eye, vec3 direction, float t) {
  vec3 p = eye + t * direction;
  vec2 q = p.xy - uCenter;
  float s = atan(q.y, q.x) * uWallRadius;  // arc length along the skyline, metres
  float R = uWallRadius;
  float footprint = t * uSampleAngle;
  // s wraps at 2 pi R; the noise is continuous except at that seam, behind a building or hill.
  float hill = R * (0.03 + 0.09 * Fbm(vec2(s / (0.35 * R), 0.5), 70u, 4, footprint / (0.35 * R)));
  float forest = smoothstep(0.45, 0.55, Fbm(vec2(s / (0.25 * R), 2.5), 72u, 3, footprint / (0.25 * R)));
  float crown_width = 0.02 * R;
  float cell = floor(s / crown_width);
  vec3 h = Hash3(ivec2(int(cell), 7), 74u);
  float u = (s / crown_width - cell) * 2.0 - 1.0;
  float crowns = forest * R * (0.02 + 0.025 * h.x) * sqrt(max(1.0 - u * u, 0.0));
  float town = (1.0 - forest) * step(0.55, Fbm(vec2(s / (0.15 * R), 4.5), 76u, 2, footprint / (0.15 * R)));
  float block_width = 0.03 * R;
  float block = floor(s / block_width);
  vec3 hb = Hash3(ivec2(int(block), 9), 78u);
  float building = town * step(0.3, hb.x) * R * (0.04 + 0.08 * hb.y);
  float top = max(hill + crowns, building);
  if (p.z > top) return vec4(0.0);
  vec3 color;
  if (building > hill + crowns && p.z < building) {
    vec2 window = fract(vec2(s, p.z) / (0.006 * R));
    float lit_window = step(0.3, window.x) * step(window.x, 0.75) * step(0.35, window.y) * step(window.y, 0.8);
    vec3 wall = mix(vec3(0.35, 0.32, 0.28), vec3(0.55, 0.5, 0.45), hb.z);
    float keep = smoothstep(1.0, 3.0, 0.006 * R / max(footprint, 1e-6));  // windows wider than a sample
    color = mix(wall, vec3(0.08, 0.09, 0.12), lit_window * keep) * (uSunColor * 0.35 + uSkyAmbient);
  } else if (p.z > hill) {
    float leaves = Fbm(vec2(s, p.z) / (0.006 * R), 82u, 4, footprint / (0.006 * R));
    color = vec3(0.04, 0.07, 0.03) * (0.5 + leaves) * (uSunColor * 0.5 + uSkyAmbient);
  } else {
    float fields = Fbm(vec2(s, p.z * 4.0) / (0.03 * R), 84u, 5, footprint / (0.03 * R));
    color = mix(vec3(0.10, 0.13, 0.05), vec3(0.22, 0.2, 0.10), fields) * (uSunColor * 0.5 + uSkyAmbient);
  }
  return vec4(color, 1.0);
}

void main() {
  vec2 pixel = vec2(gl_FragCoord.x, uTargetHeight - gl_FragCoord.y) / uSupersample;
  vec3 direction = PixelRay(pixel);
  vec3 eye = CameraCenter();
  vec3 color;
  if (uRealistic == 1) {
    vec4 object = Objects(eye, direction);
    float wall_t = WallDistance(eye, direction);
    float ground_t = direction.z < -1e-4 && eye.z > 0.0 ? -eye.z / direction.z : 1e30;
    if (object.w > 0.0 && object.w < ground_t && object.w < wall_t) {
      color = mix(object.rgb, uSkyHorizon, 1.0 - exp(-object.w / uHazeDistance));
      outColor = vec4(max(color, vec3(0.0)), 1.0);
      return;
    }
    vec4 skyline = ground_t > wall_t ? Skyline(eye, direction, wall_t) : vec4(0.0);
    if (skyline.w > 0.0) {
      color = mix(skyline.rgb, uSkyHorizon, 1.0 - exp(-wall_t / uHazeDistance));
      outColor = vec4(max(color, vec3(0.0)), 1.0);
      return;
    }
  }
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

// Whether any part of the object may fall in the view: its bounding sphere against the frame,
// grown by the sphere's projected radius (conservative; distortion is small at the edges).
bool MaySee(const View& view, const ClutterObject& object) {
  const double top = object.centre.z() + object.vertical_radius;
  const Eigen::Vector3d centre(object.centre.x(), object.centre.y(), 0.5 * top);
  const double radius = std::hypot(std::max(object.radius, object.vertical_radius), 0.5 * top) + 1e-6;
  const Eigen::Vector3d local = view.pose.ToCamera(centre);
  if (local.z() < -radius) return false;
  if (local.z() <= radius) return true;  // around the camera
  const double focal = std::max(view.camera.FocalX(), view.camera.FocalY());
  const double x = focal * local.x() / local.z() + 0.5 * view.camera.width;
  const double y = focal * local.y() / local.z() + 0.5 * view.camera.height;
  const double r = 1.5 * focal * radius / std::sqrt(std::max(local.z() * local.z() - radius * radius, 1e-12));
  return x > -r && y > -r && x < view.camera.width + r && y < view.camera.height + r;
}

}  // namespace

StudioBackdrop::StudioBackdrop(uint64_t seed, double scene_size, ClutterLayout clutter, Eigen::Vector2d centre)
    : seed_(seed), scene_size_(scene_size), clutter_(std::move(clutter)), centre_(centre) {
  if (clutter_.objects.size() > kMaxClutterObjects)
    Fail("studio backdrop: at most ", kMaxClutterObjects, " objects, got ", clutter_.objects.size());
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
  const bool realistic = !clutter_.objects.empty();
  program_.Set("uRealistic", realistic ? 1 : 0);
  if (realistic) {
    // Only the objects this view can see: the shader tests every object it is given per sample.
    std::vector<float> shapes, kinds;
    GLsizei count = 0;
    for (const ClutterObject& object : clutter_.objects) {
      if (!MaySee(view, object)) continue;
      ++count;
      shapes.insert(shapes.end(), {float(object.centre.x()), float(object.centre.y()), float(object.centre.z()),
                                   float(object.radius)});
      kinds.insert(kinds.end(),
                   {float(object.kind), float(object.vertical_radius), float(object.trunk_radius), float(object.tint)});
    }
    program_.Set("uObjectCount", static_cast<int>(count));
    if (count > 0) {
      glProgramUniform4fv(program_.id(), program_.Location("uObjectShape"), count, shapes.data());
      glProgramUniform4fv(program_.id(), program_.Location("uObjectKind"), count, kinds.data());
    }
    program_.Set("uCenter", Eigen::Vector2f(centre_.cast<float>()));
    program_.Set("uWallRadius", static_cast<float>(clutter_.wall_radius));
  }
  program_.Use();
  empty_vertex_array_.Bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  CheckGl("drawing the backdrop");
}

}  // namespace voltree
