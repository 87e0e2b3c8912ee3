#include "compress/kmeans_plus_plus.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "compress/vector_distance.h"

namespace voltree {
namespace {

// Uniform double in [0, 1) from 53 random bits: unlike std::uniform_real_distribution this is
// the same on every standard library.
double UniformUnit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// Every vector's squared distance to its nearest centre, the cells, and sums for sampling.
class SeedingState {
 public:
  explicit SeedingState(const TrainingSet& set)
      : set_(set), nearest_(set.size()), owner_(set.size(), 0), chunk_sum_((set.size() + kChunk - 1) / kChunk) {}

  // A candidate centre's effect: the vectors it would take and their new distances.
  struct Gain {
    std::vector<std::pair<uint32_t, float>> taken;
    double reduction = 0;  // of the total squared distance
  };

  void Start(const float* centre) {
    centres_.assign(centre, centre + set_.dimension);
    cells_.assign(1, std::vector<uint32_t>(set_.size()));
    std::iota(cells_[0].begin(), cells_[0].end(), 0u);
    for (size_t i = 0; i < set_.size(); ++i)
      nearest_[i] = SquaredDistance(set_.Vector(i), centre, set_.Weights(i), set_.dimension);
    cell_max_.assign(1, *std::max_element(nearest_.begin(), nearest_.end()));
    for (size_t chunk = 0; chunk < chunk_sum_.size(); ++chunk) SumChunk(chunk);
  }

  // Serial and in a fixed order, so the same for any schedule of the trials.
  Gain Evaluate(const float* candidate) const {
    Gain gain;
    const size_t centres = cells_.size();
    for (size_t a = 0; a < centres; ++a) {
      if (cells_[a].empty()) continue;
      // Plain L2: a member x of cell a can be nearer to the candidate c only if |c - a| < 2 |x - a|,
      // i.e. |c - a|^2 / 4 < nearest(x). Weighted distances are not a metric: no pruning.
      const float quarter_gap =
          set_.weighted() ? -1.f : 0.25f * SquaredDistance(candidate, Centre(a), nullptr, set_.dimension);
      if (quarter_gap >= cell_max_[a]) continue;  // not for any member of the cell
      for (uint32_t i : cells_[a]) {
        const float before = nearest_[i];
        if (quarter_gap >= before) continue;
        const float d = SquaredDistance(set_.Vector(i), candidate, set_.Weights(i), set_.dimension, before);
        if (d < before) gain.taken.emplace_back(i, d), gain.reduction += double(before) - d;
      }
    }
    return gain;
  }

  void Add(const float* centre, const Gain& gain) {
    const uint32_t k = static_cast<uint32_t>(cells_.size());
    centres_.insert(centres_.end(), centre, centre + set_.dimension);
    std::vector<char> cell_changed(cells_.size(), 0), chunk_changed(chunk_sum_.size(), 0);
    std::vector<uint32_t> members;
    for (const auto& [i, d] : gain.taken) {
      cell_changed[owner_[i]] = 1;
      chunk_changed[i / kChunk] = 1;
      nearest_[i] = d, owner_[i] = k;
      members.push_back(i);
    }
    for (size_t a = 0; a < cells_.size(); ++a) {
      if (!cell_changed[a]) continue;
      std::erase_if(cells_[a], [&](uint32_t i) { return owner_[i] != a; });
      cell_max_[a] = CellMax(cells_[a]);
    }
    cell_max_.push_back(CellMax(members));
    cells_.push_back(std::move(members));
    for (size_t chunk = 0; chunk < chunk_sum_.size(); ++chunk)
      if (chunk_changed[chunk]) SumChunk(chunk);
  }

  double Total() const { return std::accumulate(chunk_sum_.begin(), chunk_sum_.end(), 0.0); }
  float Nearest(size_t i) const { return nearest_[i]; }

  // A vector index with probability nearest / total: walks the chunk sums, then one chunk.
  size_t Sample(double total, std::mt19937_64& rng) const {
    const size_t n = nearest_.size();
    const double target = UniformUnit(rng) * total;
    double running = 0;
    size_t chunk = 0;
    while (chunk + 1 < chunk_sum_.size() && running + chunk_sum_[chunk] <= target) running += chunk_sum_[chunk++];
    for (size_t i = chunk * kChunk; i < n; ++i) {
      running += nearest_[i];
      if (running > target && nearest_[i] > 0) return i;
    }
    for (size_t i = n; i-- > 0;)
      if (nearest_[i] > 0) return i;
    return n - 1;
  }

 private:
  static constexpr size_t kChunk = 1024;

  const float* Centre(size_t a) const { return centres_.data() + a * set_.dimension; }
  float CellMax(const std::vector<uint32_t>& members) const {
    float most = 0;
    for (uint32_t i : members) most = std::max(most, nearest_[i]);
    return most;
  }
  void SumChunk(size_t chunk) {
    double sum = 0;
    for (size_t i = chunk * kChunk, end = std::min(nearest_.size(), i + kChunk); i != end; ++i) sum += nearest_[i];
    chunk_sum_[chunk] = sum;
  }

  const TrainingSet& set_;
  std::vector<float> nearest_;
  std::vector<uint32_t> owner_;
  std::vector<double> chunk_sum_;
  std::vector<float> centres_;
  std::vector<std::vector<uint32_t>> cells_;  // members of each centre
  std::vector<float> cell_max_;               // largest `nearest` in each cell
};

}  // namespace

Codebook SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials) {
  const size_t n = set.size();
  count = std::min(count, n);
  trials = std::max(trials, 1);
  Codebook codebook{set.dimension, std::vector<float>(count * set.dimension)};
  if (count == 0) return codebook;
  std::mt19937_64 rng(seed);
  SeedingState state(set);
  size_t chosen = rng() % n;
  std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(0));
  state.Start(codebook.Codeword(0));
  std::vector<size_t> candidates(trials);
  std::vector<SeedingState::Gain> gains(trials);
  for (size_t k = 1; k < count; ++k) {
    const double total = state.Total();
    if (total <= 0) {  // fewer distinct vectors than codewords: duplicates are harmless
      chosen = (chosen + 1) % n;
      std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(k));
      state.Add(codebook.Codeword(k), state.Evaluate(codebook.Codeword(k)));
      continue;
    }
    for (int t = 0; t < trials; ++t) candidates[t] = state.Sample(total, rng);
    tbb::parallel_for(0, trials, [&](int t) { gains[t] = state.Evaluate(set.Vector(candidates[t])); });
    int best = 0;  // the largest reduction, the first trial on ties
    for (int t = 1; t < trials; ++t)
      if (gains[t].reduction > gains[best].reduction) best = t;
    chosen = candidates[best];
    std::copy_n(set.Vector(chosen), set.dimension, codebook.Codeword(k));
    state.Add(codebook.Codeword(k), gains[best]);
  }
  return codebook;
}

}  // namespace voltree
