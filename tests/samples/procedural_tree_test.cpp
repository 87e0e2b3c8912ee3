#include "samples/procedural_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>

#include "core/error.h"

namespace voltree {
namespace {

// Trees are generated once per (preset, seed) and shared by the tests of this file.
const TreeMesh& Tree(TreePreset preset, uint64_t seed = 1) {
  static std::map<std::pair<int, uint64_t>, TreeMesh> cache;
  const auto key = std::make_pair(static_cast<int>(preset), seed);
  auto found = cache.find(key);
  if (found == cache.end()) found = cache.emplace(key, MakeProceduralTree({preset, seed})).first;
  return found->second;
}

const std::vector<TreePreset> kAllPresets = {TreePreset::kOak, TreePreset::kPine, TreePreset::kYoungOak};

const Image8& LeafTexture(const TreeMesh& mesh) {
  for (const Material& material : mesh.materials)
    if (material.name == kLeafMaterialName) return mesh.textures.at(material.texture);
  throw Error("no leaf material");
}

// Horizontal radius (max distance from the Z axis) of the vertices with z in [z0, z1).
float HorizontalRadius(const TreeMesh& mesh, float z0, float z1) {
  float radius = 0.0f;
  for (const MeshVertex& v : mesh.vertices)
    if (v.position.z() >= z0 && v.position.z() < z1) radius = std::max(radius, v.position.head<2>().norm());
  return radius;
}

bool SameBytes(const TreeMesh& a, const TreeMesh& b) {
  if (a.vertices.size() != b.vertices.size() || a.groups.size() != b.groups.size()) return false;
  for (size_t i = 0; i < a.vertices.size(); ++i) {
    const MeshVertex &x = a.vertices[i], &y = b.vertices[i];
    if (std::memcmp(x.position.data(), y.position.data(), sizeof(float) * 3) != 0 ||
        std::memcmp(x.normal.data(), y.normal.data(), sizeof(float) * 3) != 0 ||
        std::memcmp(x.uv.data(), y.uv.data(), sizeof(float) * 2) != 0 ||
        std::memcmp(x.tint.data(), y.tint.data(), sizeof(float) * 3) != 0)
      return false;
  }
  for (size_t g = 0; g < a.groups.size(); ++g)
    if (a.groups[g].indices != b.groups[g].indices || a.groups[g].material != b.groups[g].material) return false;
  return a.textures == b.textures;
}

TEST(ProceduralTree, PresetNamesRoundTrip) {
  EXPECT_EQ(TreePresetNames().size(), 3u);
  for (std::string_view name : TreePresetNames()) {
    const std::optional<TreePreset> preset = TreePresetFromName(name);
    ASSERT_TRUE(preset.has_value()) << name;
    EXPECT_EQ(TreePresetName(*preset), name);
  }
  EXPECT_FALSE(TreePresetFromName("baobab").has_value());
  EXPECT_THROW((TreeOptions{static_cast<TreePreset>(42), 1}.Check()), Error);
}

TEST(ProceduralTree, MeshesPassCheck) {
  for (TreePreset preset : kAllPresets) {
    const TreeMesh& mesh = Tree(preset);
    EXPECT_NO_THROW(mesh.Check()) << TreePresetName(preset);
    ASSERT_EQ(mesh.materials.size(), 2u);
    const Material& leaves = mesh.materials[1];
    EXPECT_EQ(leaves.name, kLeafMaterialName);
    EXPECT_EQ(leaves.alpha_mode, AlphaMode::kMask);
    EXPECT_TRUE(leaves.double_sided);
    for (const MeshVertex& v : mesh.vertices) {
      ASSERT_NEAR(v.normal.norm(), 1.0f, 1e-3f);
      ASSERT_TRUE(v.position.allFinite() && v.uv.allFinite());
      ASSERT_TRUE((v.tint.array() >= 0.0f).all() && (v.tint.array() <= 1.0f).all());
    }
  }
}

TEST(ProceduralTree, LeafCountsMeetPresetBounds) {
  EXPECT_GE(LeafQuadCount(Tree(TreePreset::kOak)), 20000u);
  EXPECT_LE(LeafQuadCount(Tree(TreePreset::kYoungOak)), 3000u);
  EXPECT_GE(LeafQuadCount(Tree(TreePreset::kYoungOak)), 500u);  // sparse, not bare
  EXPECT_GE(LeafQuadCount(Tree(TreePreset::kPine)), 5000u);
  // The counts do not depend on the seed.
  EXPECT_EQ(LeafQuadCount(Tree(TreePreset::kOak, 7)), LeafQuadCount(Tree(TreePreset::kOak)));
}

TEST(ProceduralTree, TriangleBudget) {
  // Measured over seeds 1..10: oak 68k..73k, pine 48k..50k, young oak 6.8k..7.5k triangles.
  EXPECT_LT(Tree(TreePreset::kOak).TriangleCount(), 150000u);
  EXPECT_LT(Tree(TreePreset::kPine).TriangleCount(), 150000u);
  EXPECT_LT(Tree(TreePreset::kYoungOak).TriangleCount(), 40000u);
}

struct ExpectedSize {
  TreePreset preset;
  float min_height, max_height, min_width, max_width;
};

TEST(ProceduralTree, NormalizedFrameAndPlausibleSize) {
  // Widths are the larger of the x and y extents. Measured over seeds 1..10: oak height
  // 9.5..10.8 m, width 10.0..11.2 m; pine 11.9..12.2 m, 7.0..8.1 m; young oak 4.8..5.3 m, 2.8..3.8 m.
  const ExpectedSize sizes[] = {{TreePreset::kOak, 9.0f, 12.0f, 8.0f, 12.5f},
                                {TreePreset::kPine, 11.0f, 13.0f, 5.0f, 9.5f},
                                {TreePreset::kYoungOak, 4.5f, 6.0f, 2.0f, 5.5f}};
  for (uint64_t seed : {1u, 2u, 3u}) {
    for (const ExpectedSize& expected : sizes) {
      const TreeMesh& mesh = Tree(expected.preset, seed);
      const auto [lo, hi] = mesh.Bounds();
      const std::string label = Str(TreePresetName(expected.preset), " seed ", seed);
      EXPECT_GE(lo.z(), 0.0f) << label;   // nothing below the ground
      EXPECT_LT(lo.z(), 0.01f) << label;  // the trunk stands on it
      EXPECT_GE(hi.z(), expected.min_height) << label;
      EXPECT_LE(hi.z(), expected.max_height) << label;
      const float width = std::max(hi.x() - lo.x(), hi.y() - lo.y());
      EXPECT_GE(width, expected.min_width) << label;
      EXPECT_LE(width, expected.max_width) << label;
      // The trunk base is at the origin: everything within 20 cm of the ground is near the axis.
      EXPECT_LT(HorizontalRadius(mesh, 0.0f, 0.2f), 1.0f) << label;
      EXPECT_GT(HorizontalRadius(mesh, 0.0f, 0.2f), 0.03f) << label;
    }
  }
}

TEST(ProceduralTree, OakTrunkIsVisibleBelowTheCrown) {
  // Between 0.3 m and 1.5 m only the trunk: nothing farther than 1 m from the axis.
  EXPECT_LT(HorizontalRadius(Tree(TreePreset::kOak), 0.3f, 1.5f), 1.0f);
}

TEST(ProceduralTree, OakLeavesCrowdTheOuterCrown) {
  // Median horizontal distance of leaf corners from the trunk axis, relative to the farthest.
  // Measured 0.50..0.56 over seeds 1..5 with the outer-shell density; 0.43..0.50 when leaves
  // are spread evenly along the twigs (a solid disc would give 0.71, a thin shell more).
  for (uint64_t seed : {1u, 2u, 3u}) {
    const TreeMesh& oak = Tree(TreePreset::kOak, seed);
    std::vector<float> distances;
    for (const MeshGroup& group : oak.groups)
      if (oak.materials[group.material].name == kLeafMaterialName)
        for (uint32_t index : group.indices) distances.push_back(oak.vertices[index].position.head<2>().norm());
    ASSERT_FALSE(distances.empty());
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    const float median = distances[distances.size() / 2];
    const float farthest = *std::max_element(distances.begin(), distances.end());
    EXPECT_GT(median / farthest, 0.48f) << "seed " << seed;
  }
}

TEST(ProceduralTree, PineIsConical) {
  const TreeMesh& pine = Tree(TreePreset::kPine);
  const float height = pine.Bounds().second.z();
  const float lower = HorizontalRadius(pine, 0.25f * height, 0.45f * height);
  const float upper = HorizontalRadius(pine, 0.75f * height, 0.95f * height);
  EXPECT_LT(upper, 0.6f * lower) << "upper " << upper << " lower " << lower;
}

TEST(ProceduralTree, SameSeedSameMeshDifferentSeedDifferentTree) {
  for (TreePreset preset : kAllPresets) {
    const TreeMesh again = MakeProceduralTree({preset, 1});
    EXPECT_TRUE(SameBytes(again, Tree(preset))) << TreePresetName(preset);
    EXPECT_FALSE(SameBytes(Tree(preset, 2), Tree(preset))) << TreePresetName(preset);
    // Different seeds move the branches, not just a few vertices.
    const auto [lo1, hi1] = Tree(preset).Bounds();
    const auto [lo2, hi2] = Tree(preset, 2).Bounds();
    EXPECT_GT((lo1 - lo2).norm() + (hi1 - hi2).norm(), 0.05f) << TreePresetName(preset);
  }
}

TEST(ProceduralTree, LeafTexturesAreCutOut) {
  for (TreePreset preset : kAllPresets) {
    const TreeMesh& mesh = Tree(preset);
    const Image8& texture = LeafTexture(mesh);
    ASSERT_EQ(texture.channels, 4);
    size_t zero = 0, full = 0, fractional = 0;
    for (size_t i = 3; i < texture.pixels.size(); i += 4) {
      const uint8_t a = texture.pixels[i];
      (a == 0 ? zero : a == 255 ? full : fractional)++;
    }
    const double texels = double(texture.width) * texture.height;
    // The leaf shapes cover part of each cell; their anti-aliased edges are fractional.
    EXPECT_GT(zero / texels, 0.2) << TreePresetName(preset);
    EXPECT_GT(full / texels, 0.1) << TreePresetName(preset);
    EXPECT_GT(fractional / texels, 0.01) << TreePresetName(preset);
    // Quad corners lie where the leaf shapes have ended, so no quad outline can show.
    for (const MeshGroup& group : mesh.groups) {
      if (mesh.materials[group.material].name != kLeafMaterialName) continue;
      for (uint32_t index : group.indices) {
        const Eigen::Vector2f uv = mesh.vertices[index].uv;
        const int x = std::clamp(static_cast<int>(uv.x() * texture.width), 0, texture.width - 1);
        const int y = std::clamp(static_cast<int>(uv.y() * texture.height), 0, texture.height - 1);
        ASSERT_EQ(texture.at(x, y, 3), 0) << TreePresetName(preset) << " uv " << uv.transpose();
      }
    }
    const Image8& bark = mesh.textures.at(mesh.materials[0].texture);
    for (size_t i = 3; i < bark.pixels.size(); i += 4) ASSERT_EQ(bark.pixels[i], 255);
  }
}

TEST(ProceduralTree, OakIsFastToGenerate) {
  // Measured 0.25..0.31 s on the loaded 2-core build machine; the spec asks for under 1 s.
  const auto start = std::chrono::steady_clock::now();
  const TreeMesh mesh = MakeProceduralTree({TreePreset::kOak, 11});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_FALSE(mesh.vertices.empty());
}

}  // namespace
}  // namespace voltree
