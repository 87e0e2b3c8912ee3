#include "samples/tree_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "samples/smoothstep.h"
#include "samples/tree_textures.h"

namespace voltree {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Eigen::Vector3f NodeTangent(const Branch& branch, size_t i) {
  const size_t last = branch.nodes.size() - 1;
  const Eigen::Vector3f& before = branch.nodes[i == 0 ? 0 : i - 1].position;
  const Eigen::Vector3f& after = branch.nodes[i == last ? last : i + 1].position;
  const Eigen::Vector3f tangent = after - before;
  return tangent.squaredNorm() > 0.0f ? Eigen::Vector3f(tangent.normalized()) : Eigen::Vector3f::UnitZ();
}

// Root buttresses: a few lobes around the trunk that fade out within a metre of the ground.
float ButtressFactor(float flare, float angle, float height, float phase) {
  const float lobe = std::pow(0.5f + 0.5f * std::cos(5.0f * angle + phase), 3.0f);
  return 1.0f + 0.6f * flare * lobe * std::exp(-height / 0.45f);
}

void AppendTube(const TreeShape& shape, const Branch& branch, float buttress_phase, TreeMesh& mesh, MeshGroup& group) {
  const int sides = std::max(3, shape.levels[branch.level].sides);
  const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  // The bark texture (1:2 aspect) covers one circumference across and two along.
  const float circumference = 2.0f * kPi * branch.nodes.front().radius;
  Eigen::Vector3f normal = AnyPerpendicular(NodeTangent(branch, 0));
  float arc = 0.0f;
  for (size_t i = 0; i < branch.nodes.size(); ++i) {
    const BranchNode& node = branch.nodes[i];
    if (i > 0) arc += (node.position - branch.nodes[i - 1].position).norm();
    const Eigen::Vector3f tangent = NodeTangent(branch, i);
    normal = (normal - tangent * normal.dot(tangent)).normalized();  // parallel transport
    const Eigen::Vector3f binormal = tangent.cross(normal);
    for (int j = 0; j <= sides; ++j) {
      const float angle = 2.0f * kPi * float(j % sides) / float(sides);
      const Eigen::Vector3f radial = std::cos(angle) * normal + std::sin(angle) * binormal;
      float radius = node.radius;
      if (branch.level == 0) radius *= ButtressFactor(shape.flare, angle, node.position.z(), buttress_phase);
      MeshVertex vertex;
      vertex.position = node.position + radial * radius;
      vertex.position.z() = std::max(vertex.position.z(), 0.0f);  // a leaning base ring meets the ground
      vertex.normal = radial;
      vertex.uv = {float(j) / float(sides), arc / (2.0f * circumference)};
      mesh.vertices.push_back(vertex);
    }
  }
  const uint32_t ring = static_cast<uint32_t>(sides + 1);
  for (uint32_t i = 0; i + 1 < branch.nodes.size(); ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(sides); ++j) {
      const uint32_t a = first + i * ring + j, b = a + 1, c = a + ring, d = c + 1;
      group.indices.insert(group.indices.end(), {a, b, d, a, d, c});
    }
  }
}

// Part of a branch that carries leaves.
struct LeafSpan {
  Eigen::Vector3f start;
  Eigen::Vector3f end;
  float length;
  float weight = 0.0f;  // share of the leaves: length times the local leaf density
};

std::vector<LeafSpan> LeafSpans(const TreeShape& shape, const Skeleton& skeleton) {
  std::vector<LeafSpan> spans;
  for (const Branch& branch : skeleton.branches) {
    if (branch.level < shape.foliage.first_level) continue;
    const float bare = shape.foliage.start * branch.Length();
    float walked = 0.0f;
    for (size_t i = 0; i + 1 < branch.nodes.size(); ++i) {
      const Eigen::Vector3f& a = branch.nodes[i].position;
      const Eigen::Vector3f& b = branch.nodes[i + 1].position;
      const float length = (b - a).norm();
      const float skip = std::clamp(bare - walked, 0.0f, length);
      walked += length;
      if (length - skip <= 1e-5f) continue;
      const Eigen::Vector3f start = a + (b - a) * (skip / length);
      spans.push_back({start, b, length - skip, 0.0f});
    }
  }
  return spans;
}

struct CrownEllipsoid {
  Eigen::Vector3f center;
  Eigen::Vector3f radii;
};

CrownEllipsoid FitCrown(const std::vector<LeafSpan>& spans) {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e9f), hi = -lo;
  for (const LeafSpan& span : spans) {
    lo = lo.cwiseMin(span.start).cwiseMin(span.end);
    hi = hi.cwiseMax(span.start).cwiseMax(span.end);
  }
  return {(lo + hi) * 0.5f, ((hi - lo) * 0.5f).cwiseMax(Eigen::Vector3f::Constant(0.3f))};
}

// Relative leaf density at normalized crown depth (0 centre, 1 surface): full in the outer shell.
float OuterDensity(float inner_density, float depth) {
  return inner_density + (1.0f - inner_density) * Smoothstep(0.35f, 0.85f, depth);
}

// Per-leaf colour: random brightness and a little yellow, darker deep inside the crown where
// real foliage is shaded by the leaves around it.
Eigen::Vector3f LeafTint(TreeRandom& random, float depth_ratio) {
  const float brightness = random.Uniform(0.78f, 1.0f);
  const float yellow = random.Uniform() * random.Uniform();
  const Eigen::Vector3f hue(0.82f + 0.18f * yellow, 0.93f + 0.07f * random.Uniform(), 0.78f + 0.12f * random.Uniform());
  const float shade = 0.75f + 0.25f * Smoothstep(0.25f, 0.95f, depth_ratio);
  return (hue * brightness * shade).cwiseMin(1.0f);
}

void AppendLeafQuad(const TreeShape& shape, const Eigen::Vector3f& anchor, const Eigen::Vector3f& twig,
                    const CrownEllipsoid& crown, TreeRandom& random, TreeMesh& mesh, MeshGroup& group) {
  const FoliageShape& foliage = shape.foliage;
  const bool needles = foliage.kind == FoliageKind::kNeedles;
  const Eigen::Vector3f offset = (anchor - crown.center).cwiseQuotient(crown.radii);
  const Eigen::Vector3f outward =
      offset.squaredNorm() > 1e-6f ? Eigen::Vector3f(offset.normalized()) : Eigen::Vector3f::UnitZ();
  // The cluster's stem follows the twig, bent outward (broad leaves reach for the light).
  Eigen::Vector3f axis = twig + random.UnitVector() * foliage.spread + outward * (needles ? 0.1f : 0.45f);
  if (!needles) axis.z() += 0.25f;
  axis.normalize();
  // Face normal as close as possible to a random mostly-outward/upward direction.
  const Eigen::Vector3f facing =
      outward * (needles ? 0.3f : 0.8f) + Eigen::Vector3f::UnitZ() * (needles ? 0.2f : 0.6f) + random.UnitVector();
  Eigen::Vector3f across = axis.cross(facing);
  if (across.squaredNorm() < 1e-8f) across = AnyPerpendicular(axis);
  across.normalize();
  Eigen::Vector3f normal = across.cross(axis).normalized();
  if (normal.dot(outward) < 0.0f) normal = -normal;
  const float size = foliage.size * (1.0f + random.Jitter(foliage.size_jitter));
  const Eigen::Vector3f base = anchor - axis * (0.04f * size);  // the stem starts inside the twig
  Eigen::Vector3f corners[4] = {base - across * (0.5f * size), base + across * (0.5f * size),
                                base + across * (0.5f * size) + axis * size,
                                base - across * (0.5f * size) + axis * size};
  float lowest = 0.0f;
  for (const Eigen::Vector3f& corner : corners) lowest = std::min(lowest, corner.z());
  for (Eigen::Vector3f& corner : corners) corner.z() -= lowest;  // keep the tree above the ground
  // One atlas cell, mirrored half of the time; its stem is at the middle of its bottom edge.
  const int cell = random.Index(kFoliageCells * kFoliageCells);
  const float cell_size = 1.0f / float(kFoliageCells);
  float u0 = float(cell % kFoliageCells) * cell_size, u1 = u0 + cell_size;
  if (random.Uniform() < 0.5f) std::swap(u0, u1);
  const float v_top = float(cell / kFoliageCells) * cell_size, v_bottom = v_top + cell_size;
  const Eigen::Vector2f uvs[4] = {{u0, v_bottom}, {u1, v_bottom}, {u1, v_top}, {u0, v_top}};
  // Shading normals lean outward so the crown reads as a volume under directional light.
  const Eigen::Vector3f shading_normal = (normal + 0.6f * outward).normalized();
  const Eigen::Vector3f tint = LeafTint(random, offset.norm());
  const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  for (int k = 0; k < 4; ++k) {
    MeshVertex vertex;
    vertex.position = corners[k];
    vertex.normal = shading_normal;
    vertex.uv = uvs[k];
    vertex.tint = tint;
    mesh.vertices.push_back(vertex);
  }
  group.indices.insert(group.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
}

}  // namespace

void AppendBranchTubes(const TreeShape& shape, const Skeleton& skeleton, TreeMesh& mesh, MeshGroup& group) {
  // A fixed buttress phase per tree, from the trunk's own geometry so it varies with the seed.
  const float phase = skeleton.branches.empty() ? 0.0f : 7.0f * skeleton.branches.front().nodes.back().position.x();
  for (const Branch& branch : skeleton.branches) AppendTube(shape, branch, phase, mesh, group);
}

size_t AppendFoliage(const TreeShape& shape, const Skeleton& skeleton, TreeRandom& random, TreeMesh& mesh,
                     MeshGroup& group) {
  std::vector<LeafSpan> spans = LeafSpans(shape, skeleton);
  const int count = shape.foliage.count;
  if (spans.empty() || count <= 0) return 0;
  const CrownEllipsoid crown = FitCrown(spans);
  double total = 0.0;
  for (LeafSpan& span : spans) {
    const float depth = ((span.start + span.end) * 0.5f - crown.center).cwiseQuotient(crown.radii).norm();
    span.weight = span.length * OuterDensity(shape.foliage.inner_density, depth);
    total += span.weight;
  }
  // Stratified along the concatenated, weighted spans: exactly `count` leaves.
  const double spacing = total / count;
  size_t span_index = 0;
  double span_begin = 0.0;
  for (int i = 0; i < count; ++i) {
    const double target = (i + 0.5 + random.Jitter(0.45f)) * spacing;
    while (span_index + 1 < spans.size() && span_begin + spans[span_index].weight < target)
      span_begin += spans[span_index++].weight;
    const LeafSpan& span = spans[span_index];
    const float u = std::clamp(static_cast<float>((target - span_begin) / span.weight), 0.0f, 1.0f);
    const Eigen::Vector3f anchor = span.start + (span.end - span.start) * u;
    const Eigen::Vector3f twig = (span.end - span.start).normalized();
    AppendLeafQuad(shape, anchor, twig, crown, random, mesh, group);
  }
  return static_cast<size_t>(count);
}

}  // namespace voltree
