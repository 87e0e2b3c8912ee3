#include "lod/branch_skeleton.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <tuple>

#include "core/error.h"
#include "lod/disjoint_sets.h"
#include "lod/leaf_separation.h"
#include "lod/surface_colour.h"

namespace voltree {
namespace {

// The bark as a graph: welded vertices (same position, one vertex), their colours and edges.
struct BarkGraph {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> colours;
  std::vector<std::vector<std::pair<int, float>>> edges;  // neighbour, length
};

BarkGraph BuildBarkGraph(const TreeMesh& mesh) {
  BarkGraph graph;
  std::map<std::tuple<float, float, float>, int> welded;
  std::vector<int> id(mesh.vertices.size(), -1);
  std::vector<Eigen::Vector3f> material_colour(mesh.materials.size());
  for (size_t m = 0; m < mesh.materials.size(); ++m)
    if (!IsLeafMaterial(mesh.materials[m])) material_colour[m] = MaterialMeanColour(mesh, static_cast<int>(m));
  std::vector<int> uses;
  for (const MeshGroup& group : mesh.groups) {
    if (IsLeafMaterial(mesh.materials[group.material])) continue;
    for (uint32_t index : group.indices) {
      if (id[index] < 0) {
        const Eigen::Vector3f& p = mesh.vertices[index].position;
        const auto [it, inserted] = welded.emplace(std::make_tuple(p.x(), p.y(), p.z()), graph.positions.size());
        if (inserted) {
          graph.positions.push_back(p);
          graph.colours.push_back(Eigen::Vector3f::Zero());
          uses.push_back(0);
        }
        id[index] = it->second;
      }
      graph.colours[id[index]] += material_colour[group.material].cwiseProduct(mesh.vertices[index].tint);
      ++uses[id[index]];
    }
  }
  for (size_t v = 0; v < graph.colours.size(); ++v) graph.colours[v] /= static_cast<float>(uses[v]);
  graph.edges.resize(graph.positions.size());
  for (const MeshGroup& group : mesh.groups) {
    if (IsLeafMaterial(mesh.materials[group.material])) continue;
    for (size_t t = 0; t + 2 < group.indices.size(); t += 3)
      for (int k = 0; k < 3; ++k) {
        const int a = id[group.indices[t + k]], b = id[group.indices[t + (k + 1) % 3]];
        if (a == b) continue;
        const float length = (graph.positions[a] - graph.positions[b]).norm();
        graph.edges[a].emplace_back(b, length);
        graph.edges[b].emplace_back(a, length);
      }
  }
  for (auto& list : graph.edges) {  // shared edges appear twice: once is enough
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return graph;
}

float MedianEdge(const BarkGraph& graph) {
  std::vector<float> lengths;
  for (const auto& list : graph.edges)
    for (const auto& [other, length] : list) lengths.push_back(length);
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

int NearestNode(const std::vector<SkeletonNode>& nodes, const Eigen::Vector3f& p) {
  int best = -1;
  float best_distance = std::numeric_limits<float>::infinity();
  for (size_t n = 0; n < nodes.size(); ++n) {
    const float distance = (nodes[n].position - p).squaredNorm();
    if (distance < best_distance) best_distance = distance, best = static_cast<int>(n);
  }
  return best;
}

// One connected piece of bark, rooted at `root`: appends its nodes, the first hanging from
// `attach` (-1: the tree's root).
void AddPiece(const BarkGraph& graph, const std::vector<int>& piece, int root, float band,
              std::vector<SkeletonNode>& nodes, int attach) {
  // Distance along the surface from everything within a band of the root, so the first band is a
  // whole ring rather than an arc around one vertex.
  std::map<int, float> distance;
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int v : piece) {
    const float d = (graph.positions[v] - graph.positions[root]).norm();
    if (d < band) distance[v] = d, queue.emplace(d, v);
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    for (const auto& [w, length] : graph.edges[v]) {
      const auto it = distance.find(w);
      if (it == distance.end() || d + length < it->second) {
        distance[w] = d + length;
        queue.emplace(d + length, w);
      }
    }
  }
  // Parts of each band: vertices of the band joined by the edges within it.
  std::map<int, int> band_of, local;
  for (const auto& [v, d] : distance)
    band_of[v] = static_cast<int>(d / band), local[v] = static_cast<int>(local.size());
  DisjointSets<int> parts(local.size());
  for (const auto& [v, b] : band_of)
    for (const auto& [w, length] : graph.edges[v])
      if (band_of.at(w) == b) parts.Join(local.at(v), local.at(w));
  // Nodes in band order (parents first), then by their smallest vertex.
  std::map<std::pair<int, int>, std::vector<int>> members;  // (band, part root) -> vertices
  for (const auto& [v, b] : band_of) members[{b, parts.Find(local.at(v))}].push_back(v);
  std::map<int, int> node_of_part;  // part root -> node index
  for (const auto& [key, vertices] : members) {
    Eigen::Vector3f centre = Eigen::Vector3f::Zero(), colour = Eigen::Vector3f::Zero();
    for (int v : vertices) centre += graph.positions[v], colour += graph.colours[v];
    centre /= static_cast<float>(vertices.size());
    colour /= static_cast<float>(vertices.size());
    float spread = 0;
    for (int v : vertices) spread += (graph.positions[v] - centre).norm();
    SkeletonNode node;
    node.position = centre;
    node.colour = colour;
    node.width = 2 * spread / static_cast<float>(vertices.size());  // a ring's mean radius, twice
    // The part of the band below that shares most edges with this one.
    std::map<int, int> shared;
    for (int v : vertices)
      for (const auto& [w, length] : graph.edges[v])
        if (band_of.at(w) == key.first - 1) ++shared[parts.Find(local.at(w))];
    int parent = -1, most = 0;
    for (const auto& [part, count] : shared)
      if (count > most && node_of_part.count(part)) most = count, parent = node_of_part.at(part);
    // The piece's first node hangs where the piece attaches; another without a part below it (a
    // second part of the first band) from the nearest node so far.
    if (parent < 0) parent = node_of_part.empty() ? attach : NearestNode(nodes, centre);
    node.parent = parent;
    node_of_part[key.second] = static_cast<int>(nodes.size());
    nodes.push_back(node);
  }
}

}  // namespace

void BranchSkeletonOptions::Check() const {
  if (!(band >= 0)) FailOption("BranchSkeletonOptions.band", "is ", band, ": give a length >= 0 (0: automatic)");
}

BranchSkeleton ExtractBranchSkeleton(const TreeMesh& mesh, const BranchSkeletonOptions& options) {
  options.Check();
  const BarkGraph graph = BuildBarkGraph(mesh);
  BranchSkeleton skeleton;
  if (graph.positions.empty()) return skeleton;
  const float band = options.band > 0 ? static_cast<float>(options.band) : std::max(2 * MedianEdge(graph), 1e-6f);
  DisjointSets<int> pieces(graph.positions.size());
  for (size_t v = 0; v < graph.edges.size(); ++v)
    for (const auto& [w, length] : graph.edges[v]) pieces.Join(static_cast<int>(v), w);
  std::map<int, std::vector<int>> by_piece;
  for (size_t v = 0; v < graph.positions.size(); ++v) by_piece[pieces.Find(static_cast<int>(v))].push_back(v);
  // Lowest pieces first (Z is up): the trunk before the branches that hang from it.
  std::vector<std::pair<float, int>> order;
  for (const auto& [root, vertices] : by_piece) {
    float lowest = std::numeric_limits<float>::infinity();
    for (int v : vertices) lowest = std::min(lowest, graph.positions[v].z());
    order.emplace_back(lowest, root);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [lowest, key] : order) {
    const std::vector<int>& piece = by_piece.at(key);
    int root = piece.front(), attach = -1;
    if (skeleton.nodes.empty()) {
      for (int v : piece)
        if (graph.positions[v].z() < graph.positions[root].z()) root = v;
    } else {  // the vertex nearest the skeleton so far, hung from that node
      float best = std::numeric_limits<float>::infinity();
      for (int v : piece) {
        const int near = NearestNode(skeleton.nodes, graph.positions[v]);
        const float distance = (skeleton.nodes[near].position - graph.positions[v]).squaredNorm();
        if (distance < best) best = distance, root = v, attach = near;
      }
    }
    AddPiece(graph, piece, root, band, skeleton.nodes, attach);
  }
  // A segment's width: the mean of its two ends' ring diameters.
  std::vector<float> ring(skeleton.nodes.size());
  for (size_t n = 0; n < ring.size(); ++n) ring[n] = skeleton.nodes[n].width;
  for (SkeletonNode& node : skeleton.nodes)
    if (node.parent >= 0) node.width = 0.5f * (node.width + ring[node.parent]);
  return skeleton;
}

std::vector<LinePrimitive> SkeletonLines(const BranchSkeleton& skeleton) {
  std::vector<LinePrimitive> lines;
  for (const SkeletonNode& node : skeleton.nodes)
    if (node.parent >= 0)
      lines.push_back({skeleton.nodes[node.parent].position, node.position, node.colour, node.width});
  return lines;
}

bool IsConnectedTree(const BranchSkeleton& skeleton) {
  int roots = 0;
  for (size_t n = 0; n < skeleton.nodes.size(); ++n) {
    const int parent = skeleton.nodes[n].parent;
    if (parent < 0) ++roots;
    // Parents come first, so following them always ends at a root.
    else if (parent >= static_cast<int>(n))
      return false;
  }
  return skeleton.nodes.empty() || roots == 1;
}

}  // namespace voltree
