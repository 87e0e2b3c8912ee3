// Union-find over the indices 0..count-1, with path halving. The smaller root wins a union, so the
// representative of a set does not depend on the order of the unions.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace voltree {

template <typename Index>
class DisjointSets {
 public:
  explicit DisjointSets(size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), Index(0)); }
  Index Find(Index x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void Join(Index a, Index b) {
    a = Find(a), b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace voltree
