#include "samples/tree_skeleton.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace voltree {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kDegree = kPi / 180.0f;
// Golden angle: successive children spiral around the parent without lining up.
constexpr float kPhyllotaxis = 137.5f * kDegree;
// Branches are kept this far above the ground plane.
constexpr float kGroundClearance = 0.05f;

struct BranchStart {
  Eigen::Vector3f position;
  Eigen::Vector3f direction;
  float length;
  float radius;
  int level;
  int parent;
};

// Where along the trunk the nodes sit: dense near the ground so the flare is smooth.
std::vector<float> NodeParameters(int level, int segments) {
  std::vector<float> t;
  if (level == 0) t = {0.0f, 0.01f, 0.025f, 0.05f};
  const float first = t.empty() ? 0.0f : 0.08f;
  for (int i = 0; i <= segments; ++i) t.push_back(first + (1.0f - first) * float(i) / float(segments));
  return t;
}

float TrunkFlare(float flare, float height_above_ground) {
  return 1.0f + flare * std::exp(-height_above_ground / 0.35f);
}

Branch GrowBranch(const TreeShape& shape, const BranchStart& start, TreeRandom& random) {
  const BranchLevel& level = shape.levels[start.level];
  Branch branch;
  branch.level = start.level;
  branch.parent = start.parent;
  const std::vector<float> ts = NodeParameters(start.level, level.segments);
  Eigen::Vector3f position = start.position;
  Eigen::Vector3f direction = start.direction.normalized();
  const float bend = level.bend_deg * kDegree;
  for (size_t i = 0; i < ts.size(); ++i) {
    const float t = ts[i];
    float radius = start.radius * (1.0f - (1.0f - level.tip_radius) * t);
    if (start.level == 0) radius *= TrunkFlare(shape.flare, position.z());
    branch.nodes.push_back({position, std::max(radius, shape.min_radius)});
    if (i + 1 == ts.size()) break;
    const float step = (ts[i + 1] - t) * start.length;
    position += direction * step;
    if (position.z() < kGroundClearance) position.z() = kGroundClearance;
    // Turns scale with the step so the shape does not depend on the node spacing.
    const float fraction = (ts[i + 1] - t) * level.segments;
    direction += random.UnitVector() * (std::tan(bend) * fraction);
    direction.z() += level.up_pull * fraction;
    if (direction.z() < 0.0f && position.z() < 4.0f * kGroundClearance) direction.z() = 0.0f;
    direction.normalize();
  }
  return branch;
}

}  // namespace

BranchFrame SampleBranch(const Branch& branch, float t) {
  const float target = t * branch.Length();
  float walked = 0.0f;
  for (size_t i = 0; i + 1 < branch.nodes.size(); ++i) {
    const BranchNode& a = branch.nodes[i];
    const BranchNode& b = branch.nodes[i + 1];
    const Eigen::Vector3f segment = b.position - a.position;
    const float length = segment.norm();
    if (walked + length >= target || i + 2 == branch.nodes.size()) {
      const float u = length > 0.0f ? std::clamp((target - walked) / length, 0.0f, 1.0f) : 0.0f;
      return {a.position + u * segment, length > 0.0f ? Eigen::Vector3f(segment / length) : Eigen::Vector3f::UnitZ(),
              a.radius + u * (b.radius - a.radius)};
    }
    walked += length;
  }
  return {branch.nodes.front().position, Eigen::Vector3f::UnitZ(), branch.nodes.front().radius};
}

namespace {

// Relative child length from where the child sits on its parent.
float ShapeFactor(const TreeShape& shape, int child_level, float t, float start) {
  if (child_level == 1) {
    const float r = std::clamp((t - start) / std::max(1e-3f, 1.0f - start), 0.0f, 1.0f);
    if (shape.crown == CrownShape::kCone) return 0.12f + 0.88f * (1.0f - r);
    return 0.15f + 0.85f * std::sin(kPi * (0.25f + 0.75f * r));
  }
  return 1.0f - 0.5f * t;  // Weber–Penn: children near the parent's base are longer
}

// Shortens a straight branch from `start` along `direction` so that its tip stays inside the
// crown envelope scaled by `reach`; never below a quarter of its length.
float FitInsideEnvelope(const CrownEnvelope& envelope, const Eigen::Vector3f& start, const Eigen::Vector3f& direction,
                        float length, float reach) {
  if (envelope.radius_xy <= 0.0f || envelope.radius_z <= 0.0f) return length;
  const Eigen::Vector3f scale(envelope.radius_xy, envelope.radius_xy, envelope.radius_z);
  const Eigen::Vector3f a = (start - Eigen::Vector3f(0.0f, 0.0f, envelope.center_z)).cwiseQuotient(scale);
  const Eigen::Vector3f b = direction.cwiseQuotient(scale);
  // |a + b t| = reach  ->  b.b t^2 + 2 a.b t + a.a - reach^2 = 0, the far root.
  const float bb = b.squaredNorm(), ab = a.dot(b), c = a.squaredNorm() - reach * reach;
  const float discriminant = ab * ab - bb * c;
  if (discriminant < 0.0f) return length;
  const float exit = (-ab + std::sqrt(discriminant)) / bb;
  return std::clamp(exit, 0.25f * length, length);
}

void SpawnChildren(const TreeShape& shape, const Branch& parent, int parent_index, TreeRandom& random,
                   std::vector<BranchStart>& out) {
  const int child_level = parent.level + 1;
  if (child_level >= static_cast<int>(shape.levels.size())) return;
  const BranchLevel& level = shape.levels[child_level];
  const float parent_length = parent.Length();
  if (parent_length < 0.05f) return;
  const float span = (1.0f - level.start) * parent_length;
  const int whorl = std::max(1, level.whorl);
  const int points = random.RoundStochastic(level.per_metre * span / float(whorl));
  float azimuth = random.Uniform(0.0f, 2.0f * kPi);
  for (int k = 0; k < points; ++k) {
    const float t = level.start + (1.0f - level.start) * (float(k) + 0.5f + random.Jitter(0.4f)) / float(points);
    const BranchFrame frame = SampleBranch(parent, t);
    const Eigen::Vector3f e1 = AnyPerpendicular(frame.direction);
    const Eigen::Vector3f e2 = frame.direction.cross(e1);
    for (int w = 0; w < whorl; ++w) {
      azimuth += whorl > 1 ? 2.0f * kPi / float(whorl) + random.Jitter(0.25f) : kPhyllotaxis + random.Jitter(0.35f);
      const float angle =
          (level.angle_deg + (level.angle_top_deg - level.angle_deg) * t + random.Jitter(level.angle_jitter_deg)) *
          kDegree;
      const Eigen::Vector3f side = std::cos(azimuth) * e1 + std::sin(azimuth) * e2;
      const Eigen::Vector3f direction = std::cos(angle) * frame.direction + std::sin(angle) * side;
      const float natural = parent_length * level.length_ratio * ShapeFactor(shape, child_level, t, level.start) *
                            (1.0f + random.Jitter(0.2f));
      const float reach = 1.0f + random.Jitter(shape.envelope.bumpiness);
      const float length = FitInsideEnvelope(shape.envelope, frame.position, direction, natural, reach);
      const float radius_ratio = std::min(0.7f, std::pow(length / parent_length, shape.radius_power));
      const float radius = std::max(shape.min_radius, frame.radius * radius_ratio);
      out.push_back({frame.position, direction, length, radius, child_level, parent_index});
    }
  }
}

}  // namespace

float Branch::Length() const {
  float length = 0.0f;
  for (size_t i = 0; i + 1 < nodes.size(); ++i) length += (nodes[i + 1].position - nodes[i].position).norm();
  return length;
}

Eigen::Vector3f AnyPerpendicular(const Eigen::Vector3f& direction) {
  const Eigen::Vector3f helper = std::abs(direction.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  return direction.cross(helper).normalized();
}

Skeleton GrowSkeleton(const TreeShape& shape, TreeRandom& random) {
  Skeleton skeleton;
  if (shape.levels.empty()) return skeleton;
  const float lean = shape.lean_deg * kDegree * random.Uniform();
  const float lean_azimuth = random.Uniform(0.0f, 2.0f * kPi);
  const Eigen::Vector3f trunk_direction(std::sin(lean) * std::cos(lean_azimuth),
                                        std::sin(lean) * std::sin(lean_azimuth), std::cos(lean));
  skeleton.branches.push_back(
      GrowBranch(shape, {Eigen::Vector3f::Zero(), trunk_direction, shape.height, shape.trunk_radius, 0, -1}, random));
  // Breadth first, so branches are stored parents before children and level by level.
  for (size_t i = 0; i < skeleton.branches.size(); ++i) {
    std::vector<BranchStart> children;
    SpawnChildren(shape, skeleton.branches[i], static_cast<int>(i), random, children);
    for (const BranchStart& child : children) skeleton.branches.push_back(GrowBranch(shape, child, random));
  }
  return skeleton;
}

}  // namespace voltree
