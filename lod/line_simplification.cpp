#include "lod/line_simplification.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace voltree {
namespace {

double SegmentDistance(const Eigen::Vector3f& p, const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const Eigen::Vector3f ab = b - a;
  const float t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f) : 0.0f;
  return static_cast<double>((a + t * ab - p).norm());
}

// The working graph: nodes with their segment's volume (the averaging weight), children lists.
class LineGraph {
 public:
  explicit LineGraph(const BranchSkeleton& skeleton)
      : nodes_(skeleton.nodes), alive_(nodes_.size(), true), volume_(nodes_.size(), 0), children_(nodes_.size()) {
    for (size_t n = 0; n < nodes_.size(); ++n) {
      if (nodes_[n].parent < 0) continue;
      children_[nodes_[n].parent].push_back(static_cast<int>(n));
      const double radius = 0.5 * nodes_[n].width;
      volume_[n] = std::numbers::pi * radius * radius * Length(static_cast<int>(n));
    }
  }

  void Apply(const LineMerge& merge) {
    const int removed = merge.removed, kept = merge.kept;
    const int parent = nodes_[removed].parent;
    if (merge.kind == LineMerge::Kind::kStraighten) {
      nodes_[kept].parent = parent;
      Replace(children_[parent], removed, kept);
    } else {
      const double a = std::max(volume_[kept], 1e-30), b = std::max(volume_[removed], 1e-30);
      nodes_[kept].position = static_cast<float>(a / (a + b)) * nodes_[kept].position +
                              static_cast<float>(b / (a + b)) * nodes_[removed].position;
      nodes_[kept].colour = static_cast<float>(a / (a + b)) * nodes_[kept].colour +
                            static_cast<float>(b / (a + b)) * nodes_[removed].colour;
      children_[parent].erase(std::find(children_[parent].begin(), children_[parent].end(), removed));
    }
    volume_[kept] += volume_[removed];
    alive_[removed] = false;
    // The merged segment keeps the summed volume over its new length.
    const double length = std::max(Length(kept), 1e-12);
    nodes_[kept].width = static_cast<float>(2 * std::sqrt(volume_[kept] / (std::numbers::pi * length)));
  }

  // The cheapest merge; none when one segment (or none) is left.
  bool Cheapest(LineMerge* best) const {
    best->cost = std::numeric_limits<double>::infinity();
    for (size_t n = 0; n < nodes_.size(); ++n) {
      if (!alive_[n]) continue;
      const int node = static_cast<int>(n), parent = nodes_[n].parent;
      if (parent >= 0 && children_[n].size() == 1) {  // straighten parent - node - child
        const int child = children_[n].front();
        const double cost = SegmentDistance(nodes_[n].position, nodes_[parent].position, nodes_[child].position);
        if (cost < best->cost) *best = {LineMerge::Kind::kStraighten, node, child, cost};
      }
      // Combine two tips of this node: the removed tip's distance from the averaged segment.
      std::vector<int> tips;
      for (int child : children_[n])
        if (children_[child].empty()) tips.push_back(child);
      for (size_t i = 0; i < tips.size(); ++i)
        for (size_t j = i + 1; j < tips.size(); ++j) {
          const int a = tips[i], b = tips[j];
          const double wa = std::max(volume_[a], 1e-30), wb = std::max(volume_[b], 1e-30);
          const Eigen::Vector3f end = static_cast<float>(wa / (wa + wb)) * nodes_[a].position +
                                      static_cast<float>(wb / (wa + wb)) * nodes_[b].position;
          const double cost = std::max(SegmentDistance(nodes_[a].position, nodes_[node].position, end),
                                       SegmentDistance(nodes_[b].position, nodes_[node].position, end));
          // The heavier tip is kept (its index if equal), so the trunk's line survives.
          const bool keep_a = wa >= wb;
          if (cost < best->cost) *best = {LineMerge::Kind::kCombine, keep_a ? b : a, keep_a ? a : b, cost};
        }
    }
    return std::isfinite(best->cost);
  }

  BranchSkeleton Skeleton() const {
    BranchSkeleton skeleton;
    std::vector<int> index(nodes_.size(), -1);
    // Parents still come first: merges only move a node's parent to an earlier node.
    for (size_t n = 0; n < nodes_.size(); ++n) {
      if (!alive_[n]) continue;
      index[n] = static_cast<int>(skeleton.nodes.size());
      SkeletonNode node = nodes_[n];
      node.parent = node.parent < 0 ? -1 : index[node.parent];
      skeleton.nodes.push_back(node);
    }
    return skeleton;
  }

 private:
  double Length(int node) const {
    const int parent = nodes_[node].parent;
    return parent < 0 ? 0.0 : static_cast<double>((nodes_[node].position - nodes_[parent].position).norm());
  }
  static void Replace(std::vector<int>& list, int from, int to) { *std::find(list.begin(), list.end(), from) = to; }

  std::vector<SkeletonNode> nodes_;
  std::vector<bool> alive_;
  std::vector<double> volume_;
  std::vector<std::vector<int>> children_;
};

}  // namespace

LineHierarchy SimplifyLines(const BranchSkeleton& skeleton) {
  LineHierarchy hierarchy;
  hierarchy.skeleton = skeleton;
  LineGraph graph(skeleton);
  LineMerge merge;
  while (graph.Cheapest(&merge)) {
    graph.Apply(merge);
    hierarchy.merges.push_back(merge);
  }
  return hierarchy;
}

BranchSkeleton LinesAfter(const LineHierarchy& hierarchy, size_t merges) {
  LineGraph graph(hierarchy.skeleton);
  for (size_t m = 0; m < std::min(merges, hierarchy.merges.size()); ++m) graph.Apply(hierarchy.merges[m]);
  return graph.Skeleton();
}

size_t MergesWithin(const LineHierarchy& hierarchy, double max_cost) {
  size_t count = 0;
  while (count < hierarchy.merges.size() && hierarchy.merges[count].cost <= max_cost) ++count;
  return count;
}

}  // namespace voltree
