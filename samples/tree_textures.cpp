#include "samples/tree_textures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <tbb/parallel_for.h>

#include "samples/smoothstep.h"
#include "samples/tree_random.h"

namespace voltree {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

int Wrap(int i, int period) { return ((i % period) + period) % period; }

float LatticeValue(int x, int y, uint64_t seed) {
  const uint64_t h = HashCombine(HashCombine(seed, static_cast<uint64_t>(static_cast<uint32_t>(x))),
                                 static_cast<uint64_t>(static_cast<uint32_t>(y)));
  return static_cast<float>(h >> 40) * 0x1.0p-24f;
}

// Tileable fractal value noise over (u, v) in [0, 1)^2: octave o has (cells_u << o) by
// (cells_v << o) lattice cells and wraps around. Lattice values are hashed once into tables.
class TileableNoise {
 public:
  TileableNoise(int cells_u, int cells_v, int octaves, uint64_t seed) {
    for (int o = 0; o < octaves; ++o) {
      Octave octave{cells_u << o, cells_v << o, {}};
      octave.values.resize(size_t(octave.period_x) * octave.period_y);
      for (int y = 0; y < octave.period_y; ++y)
        for (int x = 0; x < octave.period_x; ++x)
          octave.values[size_t(y) * octave.period_x + x] = LatticeValue(x, y, HashCombine(seed, uint64_t(o)));
      octaves_.push_back(std::move(octave));
    }
  }

  // Roughly in [0, 1).
  float operator()(float u, float v) const {
    float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
    for (const Octave& octave : octaves_) {
      sum += amplitude * octave.Evaluate(u * float(octave.period_x), v * float(octave.period_y));
      total += amplitude;
      amplitude *= 0.5f;
    }
    return sum / total;
  }

 private:
  struct Octave {
    int period_x, period_y;
    std::vector<float> values;
    float At(int x, int y) const { return values[size_t(Wrap(y, period_y)) * period_x + Wrap(x, period_x)]; }
    float Evaluate(float x, float y) const {
      const float fx = std::floor(x), fy = std::floor(y);
      const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
      const float tx = Smoothstep(0.0f, 1.0f, x - fx), ty = Smoothstep(0.0f, 1.0f, y - fy);
      const float a = At(ix, iy), b = At(ix + 1, iy), c = At(ix, iy + 1), d = At(ix + 1, iy + 1);
      return (a + (b - a) * tx) * (1.0f - ty) + (c + (d - c) * tx) * ty;
    }
  };
  std::vector<Octave> octaves_;
};

uint8_t ToByte(float x) { return static_cast<uint8_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

using Rgb = Eigen::Vector3f;  // sRGB-encoded, 0..1

Rgb Mix(const Rgb& a, const Rgb& b, float t) { return a + (b - a) * t; }

// ---- foliage shapes, in cell coordinates: x right, y up, the cell is [0, 1]^2 ----

struct FoliageShape2D {
  enum Type { kLeaf, kStroke } type = kLeaf;
  Eigen::Vector2f base;       // petiole end of a leaf, start of a stroke
  Eigen::Vector2f direction;  // unit
  float length = 0.0f;
  float half_width = 0.0f;  // relative to length for a leaf, absolute for a stroke
  float lobes = 0.0f;       // lobes per side of an oak leaf; 0: smooth
  Rgb colour = Rgb::Zero();
  Rgb rib_colour = Rgb::Zero();
  Eigen::Vector2f box_min, box_max;
};

void ComputeBox(FoliageShape2D& shape) {
  const Eigen::Vector2f tip = shape.base + shape.direction * shape.length;
  const float pad = shape.type == FoliageShape2D::kLeaf ? shape.half_width * shape.length : shape.half_width;
  shape.box_min = shape.base.cwiseMin(tip).array() - pad;
  shape.box_max = shape.base.cwiseMax(tip).array() + pad;
}

// Oak-like outline: widest past the middle, rounded lobes separated by sinuses.
float LeafEnvelope(float s, float lobes) {
  if (s <= 0.0f || s >= 1.0f) return 0.0f;
  const float body = 1.65f * std::sqrt(s) * std::pow(1.0f - s, 0.6f);
  if (lobes <= 0.0f) return body;
  return body * (0.6f + 0.4f * std::abs(std::cos(kPi * lobes * s)));
}

// The colour of `shape` at point p, or nothing where p is outside it.
std::optional<Rgb> ShadeShape(const FoliageShape2D& shape, const Eigen::Vector2f& p) {
  if ((p.array() < shape.box_min.array()).any() || (p.array() > shape.box_max.array()).any()) return std::nullopt;
  const Eigen::Vector2f d = p - shape.base;
  const float along = d.dot(shape.direction);
  const float across = shape.direction.x() * d.y() - shape.direction.y() * d.x();
  if (shape.type == FoliageShape2D::kStroke) {
    const float s = along / shape.length;
    if (s < 0.0f || s > 1.0f) return std::nullopt;
    const float width = shape.half_width * (1.0f - 0.6f * s);  // needles taper to a point
    if (std::abs(across) > width) return std::nullopt;
    return Mix(shape.colour, shape.rib_colour, 1.0f - std::abs(across) / width);
  }
  const float s = along / shape.length;
  const float t = across / (shape.half_width * shape.length);
  const float envelope = LeafEnvelope(s, shape.lobes);
  if (std::abs(t) > envelope) return std::nullopt;
  const float edge = std::abs(t) / envelope;
  Rgb colour = shape.colour * (0.82f + 0.18f * (1.0f - edge));
  if (std::abs(t) < 0.045f) colour = shape.rib_colour;  // midrib
  // Lateral veins toward the lobes.
  const float vein_phase = std::abs(s * 2.0f * shape.lobes - std::abs(t) * 1.2f);
  if (shape.lobes > 0.0f && std::abs(vein_phase - std::round(vein_phase)) < 0.06f && s > 0.1f)
    colour = Mix(colour, shape.rib_colour, 0.45f);
  return colour;
}

Eigen::Vector2f DirectionFromVertical(float angle) { return {std::sin(angle), std::cos(angle)}; }

// Length that keeps a shape from base along direction inside the cell with a margin.
float FitLength(const Eigen::Vector2f& base, const Eigen::Vector2f& direction, float length, float margin) {
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector2f tip = base + direction * length;
    if (tip.x() > margin && tip.x() < 1.0f - margin && tip.y() > margin && tip.y() < 1.0f - margin) break;
    length *= 0.9f;
  }
  return length;
}

// An oak shoot: a short twig ending in a rosette of lobed leaves that fans out over the cell.
std::vector<FoliageShape2D> LeafCluster(TreeRandom& random) {
  std::vector<FoliageShape2D> shapes;
  const Rgb stem_colour(0.36f, 0.30f, 0.20f);
  FoliageShape2D stem;
  stem.type = FoliageShape2D::kStroke;
  stem.base = {0.5f, 0.0f};
  stem.direction = DirectionFromVertical(random.Jitter(0.12f));
  stem.length = random.Uniform(0.3f, 0.4f);
  stem.half_width = 0.014f;
  stem.colour = stem_colour * 0.8f;
  stem.rib_colour = stem_colour;
  ComputeBox(stem);
  shapes.push_back(stem);
  const float stem_angle = std::atan2(stem.direction.x(), stem.direction.y());
  const int leaves = 5 + random.Index(3);
  for (int k = 0; k < leaves; ++k) {
    FoliageShape2D leaf;
    // Fanned from one side to the other, drawn outer leaves first so the middle ones overlap.
    const int order = (k % 2 == 0) ? k / 2 : leaves - 1 - k / 2;
    const float fan = -1.0f + 2.0f * float(order) / float(leaves - 1);
    const float angle = stem_angle + fan * 1.45f + random.Jitter(0.15f);
    leaf.base = stem.base + stem.direction * (stem.length * random.Uniform(0.7f, 1.0f));
    leaf.direction = DirectionFromVertical(angle);
    const float reach = 0.56f - 0.12f * std::abs(fan);  // side leaves are shorter, as on real shoots
    leaf.length = FitLength(leaf.base, leaf.direction, reach * random.Uniform(0.85f, 1.0f), 0.02f);
    leaf.half_width = random.Uniform(0.25f, 0.31f);
    leaf.lobes = random.Uniform(3.5f, 5.0f);
    const float green = random.Uniform(0.0f, 1.0f);
    leaf.colour = Mix(Rgb(0.22f, 0.38f, 0.12f), Rgb(0.36f, 0.50f, 0.16f), green);
    leaf.rib_colour = Mix(leaf.colour, Rgb(0.62f, 0.66f, 0.34f), 0.5f);
    ComputeBox(leaf);
    shapes.push_back(leaf);
  }
  return shapes;
}

// A pine shoot: a twig with a bottle brush of needles.
std::vector<FoliageShape2D> NeedleShoot(TreeRandom& random) {
  std::vector<FoliageShape2D> shapes;
  FoliageShape2D stem;
  stem.type = FoliageShape2D::kStroke;
  stem.base = {0.5f, 0.0f};
  stem.direction = DirectionFromVertical(random.Jitter(0.1f));
  stem.length = 0.9f;
  stem.half_width = 0.016f;
  stem.colour = Rgb(0.30f, 0.24f, 0.16f);
  stem.rib_colour = Rgb(0.42f, 0.34f, 0.22f);
  ComputeBox(stem);
  shapes.push_back(stem);
  const float stem_angle = std::atan2(stem.direction.x(), stem.direction.y());
  const int needles = 80 + random.Index(30);
  for (int k = 0; k < needles; ++k) {
    FoliageShape2D needle;
    needle.type = FoliageShape2D::kStroke;
    const float along = random.Uniform(0.06f, 0.97f);
    const float side = random.Uniform() < 0.5f ? 1.0f : -1.0f;
    needle.base = stem.base + stem.direction * (along * stem.length);
    needle.direction = DirectionFromVertical(stem_angle + side * random.Uniform(0.35f, 1.05f));
    const float taper = 1.0f - 0.45f * along;  // shorter needles toward the growing tip
    needle.length = FitLength(needle.base, needle.direction, random.Uniform(0.26f, 0.36f) * taper, 0.01f);
    needle.half_width = 0.010f;
    const float shade = random.Uniform();
    needle.colour = Mix(Rgb(0.12f, 0.24f, 0.10f), Rgb(0.20f, 0.34f, 0.14f), shade);
    needle.rib_colour = Mix(needle.colour, Rgb(0.34f, 0.46f, 0.22f), 0.6f);
    ComputeBox(needle);
    shapes.push_back(needle);
  }
  return shapes;
}

bool BoxesOverlap(const FoliageShape2D& shape, const Eigen::Vector2f& lo, const Eigen::Vector2f& hi) {
  return (shape.box_min.array() <= hi.array()).all() && (shape.box_max.array() >= lo.array()).all();
}

// Rasterizes row y of one cell with 4x4 supersampling; later shapes are drawn over earlier ones.
void DrawCellRow(const std::vector<FoliageShape2D>& shapes, const Rgb& fill, int x0, int y0, int cell, int y,
                 Image8& image) {
  constexpr int kSub = 4;
  std::vector<const FoliageShape2D*> nearby;  // shapes whose box touches the texel, topmost first
  for (int x = 0; x < cell; ++x) {
    // Image rows go down, cell y goes up.
    const Eigen::Vector2f texel_lo(float(x) / float(cell), 1.0f - float(y + 1) / float(cell));
    const Eigen::Vector2f texel_hi(float(x + 1) / float(cell), 1.0f - float(y) / float(cell));
    nearby.clear();
    for (auto shape = shapes.rbegin(); shape != shapes.rend(); ++shape)
      if (BoxesOverlap(*shape, texel_lo, texel_hi)) nearby.push_back(&*shape);
    Rgb sum = Rgb::Zero();
    int covered = 0;
    for (int sy = 0; sy < kSub && !nearby.empty(); ++sy) {
      for (int sx = 0; sx < kSub; ++sx) {
        const Eigen::Vector2f p((float(x) + (float(sx) + 0.5f) / kSub) / float(cell),
                                1.0f - (float(y) + (float(sy) + 0.5f) / kSub) / float(cell));
        for (const FoliageShape2D* shape : nearby) {
          if (const std::optional<Rgb> colour = ShadeShape(*shape, p)) {
            sum += *colour;
            ++covered;
            break;
          }
        }
      }
    }
    const Rgb colour = covered > 0 ? Rgb(sum / float(covered)) : fill;
    for (int c = 0; c < 3; ++c) image.at(x0 + x, y0 + y, c) = ToByte(colour[c]);
    image.at(x0 + x, y0 + y, 3) = ToByte(float(covered) / float(kSub * kSub));
  }
}

}  // namespace

Image8 MakeBarkTexture(uint64_t seed, int width, int height) {
  Image8 image(width, height, 4, 255);
  constexpr int kRidges = 8;  // furrows around the circumference
  const uint64_t crack_seed = HashCombine(seed, 3);
  const TileableNoise warp_noise(3, 4, 4, HashCombine(seed, 1)), fibre_noise(48, 6, 3, HashCombine(seed, 2)),
      wave_noise(16, 8, 1, crack_seed), width_noise(8, 6, 2, HashCombine(seed, 4)),
      tone_noise(2, 2, 2, HashCombine(seed, 5));
  const Rgb furrow(0.13f, 0.10f, 0.08f), plate(0.50f, 0.46f, 0.40f);
  // Rows are independent, so the parallel result is the same as the serial one.
  tbb::parallel_for(0, height, [&](int y) {
    const float v = float(y) / float(height);
    for (int x = 0; x < width; ++x) {
      const float u = float(x) / float(width);
      // Ridges wander sideways and merge, like the interlaced furrows of oak bark.
      const float warp = warp_noise(u, v) - 0.5f;
      const float phase = u * kRidges + 2.2f * warp;
      const float ridge = 0.5f - 0.5f * std::cos(2.0f * kPi * phase);
      const float furrow_width = 0.04f + 0.3f * width_noise(u, v);
      float relief = Smoothstep(0.0f, furrow_width + 0.2f, ridge - furrow_width * 0.5f);
      // Plates broken by short, wavy horizontal cracks, offset per ridge and not on every plate.
      const int column = static_cast<int>(std::floor(phase));
      const float offset = LatticeValue(Wrap(column, kRidges), 0, crack_seed);
      const float wave = 0.15f * (wave_noise(u, v) - 0.5f);
      const float crack_line = std::abs(std::fmod(v * 5.0f + offset + wave + 10.0f, 1.0f) - 0.5f);
      const float crack_mask =
          Smoothstep(0.45f, 0.6f, LatticeValue(Wrap(column, kRidges), 1 + int(v * 5.0f + offset), crack_seed));
      relief *= 1.0f - 0.7f * crack_mask * Smoothstep(0.465f, 0.5f, crack_line);
      // Fine vertical fibres and broad tone changes (lichen-grey to brown).
      const float fibre = fibre_noise(u, v);
      const float tone = tone_noise(u, v);
      const Rgb plate_colour = Mix(plate, Rgb(0.44f, 0.36f, 0.27f), tone);
      const Rgb colour = Mix(furrow, plate_colour, relief) * (0.78f + 0.4f * fibre);
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = ToByte(colour[c]);
    }
  });
  return image;
}

Image8 MakeFoliageTexture(FoliageKind kind, uint64_t seed, int size) {
  Image8 image(size, size, 4, 0);
  const int cell = size / kFoliageCells;
  TreeRandom random(HashCombine(seed, 0xF0));
  const Rgb fill = kind == FoliageKind::kNeedles ? Rgb(0.16f, 0.29f, 0.12f) : Rgb(0.29f, 0.44f, 0.14f);
  // Shapes are drawn serially from the seed, then rasterized row by row in parallel.
  std::vector<std::vector<FoliageShape2D>> cells;
  for (int i = 0; i < kFoliageCells * kFoliageCells; ++i)
    cells.push_back(kind == FoliageKind::kNeedles ? NeedleShoot(random) : LeafCluster(random));
  tbb::parallel_for(0, cell * kFoliageCells, [&](int y) {
    const int cy = y / cell;
    for (int cx = 0; cx < kFoliageCells; ++cx)
      DrawCellRow(cells[size_t(cy) * kFoliageCells + cx], fill, cx * cell, cy * cell, cell, y - cy * cell, image);
  });
  return image;
}

}  // namespace voltree
