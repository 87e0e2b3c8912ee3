#include "lod/surface_colour.h"

#include <algorithm>
#include <cmath>

#include "core/srgb.h"

namespace voltree {
namespace {

Eigen::Vector3f LinearBase(const Material& material) {
  return {SrgbToLinear(material.base_color[0]), SrgbToLinear(material.base_color[1]),
          SrgbToLinear(material.base_color[2])};
}

}  // namespace

Eigen::Vector4f MaterialSample(const TreeMesh& mesh, int material, const Eigen::Vector2f& uv) {
  const Material& m = mesh.materials[material];
  Eigen::Vector4f sample(1, 1, 1, 1);
  if (m.texture >= 0) {
    const Image8& texture = mesh.textures[m.texture];
    const float u = uv.x() - std::floor(uv.x()), v = uv.y() - std::floor(uv.y());
    const int x = std::clamp(static_cast<int>(u * static_cast<float>(texture.width)), 0, texture.width - 1);
    const int y = std::clamp(static_cast<int>(v * static_cast<float>(texture.height)), 0, texture.height - 1);
    for (int c = 0; c < 3; ++c) sample[c] = SrgbToLinear(texture.at(x, y, std::min(c, texture.channels - 1)) / 255.0f);
    sample[3] = texture.channels == 4 ? texture.at(x, y, 3) / 255.0f : 1.0f;
  }
  sample.head<3>() = sample.head<3>().cwiseProduct(LinearBase(m));
  sample[3] *= m.base_color[3];
  return sample;
}

Eigen::Vector3f MaterialMeanColour(const TreeMesh& mesh, int material) {
  const Material& m = mesh.materials[material];
  if (m.texture < 0) return LinearBase(m);
  const Image8& texture = mesh.textures[m.texture];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight = 0;
  for (int y = 0; y < texture.height; ++y)
    for (int x = 0; x < texture.width; ++x) {
      const double alpha = texture.channels == 4 ? texture.at(x, y, 3) / 255.0 : 1.0;
      for (int c = 0; c < 3; ++c)
        sum[c] += alpha * SrgbToLinear(texture.at(x, y, std::min(c, texture.channels - 1)) / 255.0f);
      weight += alpha;
    }
  if (weight <= 0) return LinearBase(m);
  return (sum / weight).cast<float>().cwiseProduct(LinearBase(m));
}

std::vector<Eigen::Vector3f> LeafColours(const TreeMesh& mesh, const std::vector<Leaf>& leaves) {
  std::vector<Eigen::Vector3f> means(mesh.materials.size());
  std::vector<bool> known(mesh.materials.size(), false);
  std::vector<Eigen::Vector3f> colours;
  colours.reserve(leaves.size());
  for (const Leaf& leaf : leaves) {
    const MeshGroup& group = mesh.groups[leaf.group];
    if (!known[group.material]) {
      means[group.material] = MaterialMeanColour(mesh, group.material);
      known[group.material] = true;
    }
    Eigen::Vector3f tint = Eigen::Vector3f::Zero();
    for (uint32_t triangle : leaf.triangles)
      for (int corner = 0; corner < 3; ++corner) tint += mesh.vertices[group.indices[3 * triangle + corner]].tint;
    tint /= static_cast<float>(3 * std::max<size_t>(leaf.triangles.size(), 1));
    colours.push_back(means[group.material].cwiseProduct(tint));
  }
  return colours;
}

}  // namespace voltree
