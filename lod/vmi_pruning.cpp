#include "lod/vmi_pruning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.h"

namespace voltree {
namespace {

struct Histograms {
  std::vector<double> total;       // visible leaf pixels per view
  std::vector<double> mean_share;  // p(o)
  std::vector<double> weighted;    // per view: sum_o a_o log(a_o / p(o))
};

Histograms Summarize(const std::vector<std::vector<uint32_t>>& pixels) {
  const size_t views = pixels.size(), leaves = views ? pixels[0].size() : 0;
  Histograms h{std::vector<double>(views, 0), std::vector<double>(leaves, 0), std::vector<double>(views, 0)};
  for (size_t v = 0; v < views; ++v) {
    if (pixels[v].size() != leaves) Fail("lod: views count different numbers of leaves");
    for (uint32_t a : pixels[v]) h.total[v] += a;
    if (h.total[v] > 0)
      for (size_t o = 0; o < leaves; ++o) h.mean_share[o] += pixels[v][o] / h.total[v] / static_cast<double>(views);
  }
  for (size_t v = 0; v < views; ++v)
    for (size_t o = 0; o < leaves; ++o)
      if (const double a = pixels[v][o]; a > 0) h.weighted[v] += a * std::log(a / h.mean_share[o]);
  return h;
}

// I(v; F) = sum_o (a_o / A) log(a_o / (A p(o))) = weighted / A - log A.
double Vmi(double weighted, double total) { return total > 0 ? weighted / total - std::log(total) : 0.0; }

}  // namespace

std::vector<double> ViewpointMutualInformation(const std::vector<std::vector<uint32_t>>& pixels) {
  const Histograms h = Summarize(pixels);
  std::vector<double> vmi(pixels.size());
  for (size_t v = 0; v < pixels.size(); ++v) vmi[v] = Vmi(h.weighted[v], h.total[v]);
  return vmi;
}

std::vector<double> LeafRemovalCosts(const std::vector<std::vector<uint32_t>>& pixels) {
  const Histograms h = Summarize(pixels);
  const size_t leaves = pixels.empty() ? 0 : pixels[0].size();
  std::vector<double> costs(leaves, 0);
  for (size_t v = 0; v < pixels.size(); ++v) {
    const double before = Vmi(h.weighted[v], h.total[v]);
    for (size_t o = 0; o < leaves; ++o) {
      const double a = pixels[v][o];
      if (a == 0) continue;  // p(o) held fixed: an unseen leaf changes nothing here
      costs[o] += std::abs(before - Vmi(h.weighted[v] - a * std::log(a / h.mean_share[o]), h.total[v] - a));
    }
  }
  return costs;
}

std::vector<VmiRemoval> VmiRemovalSequence(LeafIdRenderer& ids, size_t leaf_count, const std::vector<View>& views,
                                           size_t keep, double round_fraction) {
  if (!(round_fraction > 0 && round_fraction <= 1)) Fail("lod: VMI round fraction ", round_fraction, " not in (0, 1]");
  std::vector<uint8_t> drawn(leaf_count, 1);
  size_t remaining = leaf_count;
  std::vector<VmiRemoval> sequence;
  while (remaining > keep) {
    std::vector<std::vector<uint32_t>> pixels;
    for (const View& view : views) pixels.push_back(ids.VisiblePixels(view, drawn));
    const std::vector<double> costs = LeafRemovalCosts(pixels);
    std::vector<uint32_t> candidates;
    for (uint32_t i = 0; i < leaf_count; ++i)
      if (drawn[i]) candidates.push_back(i);
    // Cheapest first; ties (unseen leaves) by index, so the sequence is deterministic.
    std::stable_sort(candidates.begin(), candidates.end(), [&](uint32_t a, uint32_t b) { return costs[a] < costs[b]; });
    const size_t count =
        std::min(remaining - keep, std::max<size_t>(1, static_cast<size_t>(std::ceil(round_fraction * remaining))));
    double largest = 0;
    for (uint32_t i : candidates) largest = std::max(largest, costs[i]);
    for (size_t k = 0; k < count; ++k) {
      const uint32_t leaf = candidates[k];
      sequence.push_back({leaf, largest > 0 ? costs[leaf] / largest : 0.0});
      drawn[leaf] = 0;
    }
    remaining -= count;
  }
  return sequence;
}

std::vector<LeafDraw> VmiLeafDraws(const std::vector<Leaf>& leaves, const std::vector<VmiRemoval>& sequence,
                                   size_t removals) {
  if (removals > sequence.size()) Fail("lod: ", removals, " VMI removals asked of a sequence of ", sequence.size());
  std::vector<double> size(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) size[i] = leaves[i].area;
  std::vector<uint8_t> alive(leaves.size(), 1);
  for (size_t r = 0; r < removals; ++r) {
    const uint32_t gone = sequence[r].leaf;
    alive[gone] = 0;
    // The nearest remaining leaf by centre distance (ties: the lower index).
    uint32_t nearest = std::numeric_limits<uint32_t>::max();
    float best = std::numeric_limits<float>::infinity();
    for (uint32_t i = 0; i < leaves.size(); ++i) {
      if (!alive[i]) continue;
      const float d = (leaves[i].centre - leaves[gone].centre).squaredNorm();
      if (d < best) best = d, nearest = i;
    }
    if (nearest != std::numeric_limits<uint32_t>::max()) size[nearest] += size[gone] * sequence[r].cost;
  }
  std::vector<LeafDraw> draws;
  for (uint32_t i = 0; i < leaves.size(); ++i)
    if (alive[i]) draws.push_back({i, leaves[i].area > 0 ? size[i] / leaves[i].area : 1.0});
  return draws;
}

}  // namespace voltree
