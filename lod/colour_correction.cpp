#include "lod/colour_correction.h"

#include <cmath>

#include "core/error.h"

namespace voltree {
namespace {

Eigen::Vector3d WeightedMean(const std::vector<Eigen::Vector3f>& colours, const std::vector<double>& weights) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0;
  for (size_t i = 0; i < colours.size(); ++i) sum += weights[i] * colours[i].cast<double>(), total += weights[i];
  return total > 0 ? Eigen::Vector3d(sum / total) : Eigen::Vector3d::Zero();
}

}  // namespace

std::vector<Eigen::Vector3f> CorrectedLeafColours(const std::vector<Eigen::Vector3f>& colours,
                                                  const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws,
                                                  double contrast) {
  if (!(contrast >= 0 && contrast <= 1)) Fail("lod: the contrast factor ", contrast, " is outside [0, 1]");
  if (colours.size() != leaves.size()) Fail("lod: ", colours.size(), " leaf colours for ", leaves.size(), " leaves");
  std::vector<double> areas;
  for (const Leaf& leaf : leaves) areas.push_back(leaf.area);
  const Eigen::Vector3d full = WeightedMean(colours, areas);
  std::vector<Eigen::Vector3f> kept;
  std::vector<double> drawn_areas;
  for (const LeafDraw& draw : draws) {
    if (draw.leaf >= leaves.size()) Fail("lod: leaf ", draw.leaf, " out of range (", leaves.size(), " leaves)");
    kept.push_back(colours[draw.leaf]);
    drawn_areas.push_back(leaves[draw.leaf].area * draw.area_scale);
  }
  const Eigen::Vector3d survivors = WeightedMean(kept, drawn_areas);
  std::vector<Eigen::Vector3f> corrected;
  corrected.reserve(kept.size());
  for (const Eigen::Vector3f& colour : kept)
    corrected.push_back((full + contrast * (colour.cast<double>() - survivors)).cwiseMax(0.0).cast<float>());
  return corrected;
}

double ContrastFactor(double lambda) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: the kept fraction lambda = ", lambda, " is outside (0, 1]");
  return std::sqrt(lambda);
}

TreeMesh WithLeafColours(const TreeMesh& mesh, const std::vector<Leaf>& leaves, const std::vector<LeafDraw>& draws,
                         const std::vector<Eigen::Vector3f>& colours, const std::vector<Eigen::Vector3f>& corrected) {
  if (corrected.size() != draws.size())
    Fail("lod: ", corrected.size(), " corrected colours for ", draws.size(), " leaves");
  TreeMesh out = mesh;
  std::vector<bool> done(mesh.vertices.size(), false);  // a vertex belongs to one leaf; tint it once
  for (size_t k = 0; k < draws.size(); ++k) {
    const Leaf& leaf = leaves.at(draws[k].leaf);
    Eigen::Vector3f factor = Eigen::Vector3f::Ones();
    for (int c = 0; c < 3; ++c)
      if (colours[draws[k].leaf][c] > 0) factor[c] = corrected[k][c] / colours[draws[k].leaf][c];
    const std::vector<uint32_t>& indices = mesh.groups.at(leaf.group).indices;
    for (uint32_t triangle : leaf.triangles)
      for (int corner = 0; corner < 3; ++corner) {
        const uint32_t index = indices[3 * triangle + corner];
        if (done[index]) continue;
        done[index] = true;
        out.vertices[index].tint = out.vertices[index].tint.cwiseProduct(factor);
      }
  }
  return out;
}

}  // namespace voltree
