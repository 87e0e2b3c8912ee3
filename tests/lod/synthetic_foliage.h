// A tree mesh small enough to reason about: one bark triangle (opaque) and `leaves` square leaf
// cards of a "leaves" material, each of side `side`, at seeded positions in a unit cube.
#pragma once

#include <cstdint>

#include "samples/tree_mesh.h"

namespace voltree::test {

inline TreeMesh SyntheticFoliage(int leaves, float side, uint64_t seed = 7, bool welded = true) {
  TreeMesh mesh;
  mesh.materials.push_back(Material{.name = "bark"});
  Material leaf{.name = "leaves"};
  leaf.alpha_mode = AlphaMode::kMask;
  mesh.materials.push_back(leaf);
  const auto vertex = [](float x, float y, float z) {
    MeshVertex v;
    v.position = {x, y, z};
    return v;
  };
  mesh.vertices = {vertex(-0.1f, 0, 0), vertex(0.1f, 0, 0), vertex(0, 0, 1)};
  mesh.groups.push_back(MeshGroup{0, {0, 1, 2}});
  MeshGroup cards{1, {}};
  uint64_t state = seed;
  const auto next = [&state] {  // a small LCG: positions only need to differ
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  };
  for (int i = 0; i < leaves; ++i) {
    const float x = next(), y = next(), z = 0.5f + next();
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(vertex(x, y, z));
    mesh.vertices.push_back(vertex(x + side, y, z));
    mesh.vertices.push_back(vertex(x + side, y, z + side));
    mesh.vertices.push_back(vertex(x, y, z + side));
    if (welded) {
      cards.indices.insert(cards.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    } else {  // the second triangle gets copies of the shared corners
      mesh.vertices.push_back(vertex(x, y, z));
      mesh.vertices.push_back(vertex(x + side, y, z + side));
      cards.indices.insert(cards.indices.end(), {base, base + 1, base + 2, base + 4, base + 5, base + 3});
    }
  }
  mesh.groups.push_back(cards);
  return mesh;
}

}  // namespace voltree::test
