// A textured triangle mesh of a tree in the normalized tree frame (+Z up, origin at the trunk
// base), as made by the procedural generator or imported from glTF/OBJ, ready for the studio.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace voltree {

struct MeshVertex {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  Eigen::Vector2f uv = Eigen::Vector2f::Zero();
  // Per-vertex tint multiplied with the material colour (leaf colour variation); linear 0..1.
  Eigen::Vector3f tint = Eigen::Vector3f::Ones();
};

enum class AlphaMode { kOpaque, kMask, kBlend };

struct Material {
  std::string name;
  Eigen::Vector4f base_color = Eigen::Vector4f::Ones();  // sRGB-encoded RGB, straight alpha
  int texture = -1;                                      // index into TreeMesh::textures, -1: none
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float alpha_cutoff = 0.5f;  // for kMask
  bool double_sided = false;  // leaves: lit from both sides
};

// Triangles that share one material.
struct MeshGroup {
  int material = 0;
  std::vector<uint32_t> indices;  // three per triangle, into TreeMesh::vertices
};

// The alpha below which a fragment of this material is discarded; -1 for opaque materials. Blended
// materials are cut at 0.5: supersampling turns the cut edges into fractional alpha.
float AlphaCutoff(const Material& material);

struct TreeMesh {
  std::vector<MeshVertex> vertices;
  std::vector<MeshGroup> groups;
  std::vector<Material> materials;
  std::vector<Image8> textures;  // sRGB RGBA8, straight alpha

  size_t TriangleCount() const;
  // Axis-aligned bounds of all vertices; {min, max}.
  std::pair<Eigen::Vector3f, Eigen::Vector3f> Bounds() const;
  // The crown the studio's light shades: bounds of the vertices of alpha-tested or blended (leaf)
  // materials, else Bounds().
  std::pair<Eigen::Vector3f, Eigen::Vector3f> CrownBounds() const;
  // Throws Error when an index, material or texture reference is out of range or empty.
  void Check() const;
};

}  // namespace voltree
