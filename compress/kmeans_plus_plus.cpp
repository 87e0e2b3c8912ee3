#include "compress/kmeans_plus_plus.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "compress/center_bounds.h"
#include "compress/nearest_codeword.h"
#include "compress/principal_axes.h"
#include "compress/vector_distance.h"
#include "core/check.h"
#include "core/cpu_features.h"
#include "core/huge_page_allocator.h"

namespace voltree {
namespace {

// Uniform double in [0, 1) from 53 random bits: unlike std::uniform_real_distribution this is
// the same on every standard library.
double UniformUnit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// All cells' members in one arena, cell after cell, so no step allocates: a new cell is appended,
// and members that move on stay behind as gaps (nearest = 0) until the arena is full and is
// compacted in place. Only the sketches are read in bulk; the few vectors that pass are read
// from the training set.
struct Arena {
  HugePageVector<uint32_t> index;  // training vector
  HugePageVector<float> key;       // squared distance to its cell's centre when it joined (sort key)
  HugePageVector<float> nearest;   // the same while it stays; 0 once it has moved on
  HugePageVector<Sketch> sketch;   // relative to its cell's centre
};

struct Cell {
  uint32_t centre = 0;        // the training vector chosen as its centre
  size_t begin = 0, end = 0;  // members in the arena, sorted by key (then index)
  double potential = 0;       // sum of nearest, in order
};

// The position p of `values` (squared distances, summing to the potential over [0, positions))
// where the running sum first passes `target` = uniform * potential, never one of value 0: the
// k-means++ draw. `groups` consecutive runs of positions, given by their sums and first
// positions, are walked first, so only one run is scanned value by value.
template <class GroupSum, class GroupBegin>
size_t DrawPosition(double target, size_t groups, GroupSum group_sum, GroupBegin group_begin, const float* values,
                    size_t positions) {
  double running = 0;
  size_t g = 0;
  while (g + 1 < groups && running + group_sum(g) <= target) running += group_sum(g++);
  for (size_t p = groups ? group_begin(g) : 0; p < positions; ++p) {
    running += values[p];
    if (running > target && values[p] > 0) return p;
  }
  for (size_t p = positions; p-- > 0;)  // rounding left the target beyond the last value
    if (values[p] > 0) return p;
  return 0;
}

// A vector about to join a new cell, with its squared distance to the cell's centre.
struct Joiner {
  uint32_t index;
  float distance;
  bool operator<(const Joiner& other) const {
    return distance < other.distance || (distance == other.distance && index < other.index);
  }
};

// Greedy k-means++ state for plain L2, where the bounds of centre_bounds.h hold. The trials of one
// step are measured in one pass. Every sum runs in a fixed order (cells, then chunks, in order),
// so the result does not depend on the number of threads.
class BoundedSeeding {
 public:
  // Starts from training vector `first_centre` as centre 0: one cell holding every vector.
  BoundedSeeding(const TrainingSet& set, uint32_t first_centre, bool use_simd)
      : set_(set), avx2_(use_simd && CpuHasAvx2Fma()) {
    const size_t n = set.size();
    axes_ = FindPrincipalAxes(set, kSketchAxes);
    projected_.resize(n * axes_.count);
    axes_.ProjectAll(set, projected_.data());
    const size_t capacity = n + n / 2 + 1;  // compacted about every n / 2 moves
    arena_.index.resize(capacity);
    arena_.key.resize(capacity);
    arena_.nearest.resize(capacity);
    arena_.sketch.resize(capacity);
    std::vector<Joiner> everyone(n);
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      everyone[i] = {uint32_t(i), SquaredDistance(set.Vector(i), set.Vector(first_centre), nullptr, set.dimension)};
    });
    AddCell(std::move(everyone), first_centre);
  }

  double Potential() const {
    double sum = 0;
    for (const Cell& cell : cells_) sum += cell.potential;
    return sum;
  }

  // A vector drawn with probability nearest / potential (never one that sits on a centre).
  size_t Sample(double unit) const {
    const size_t m = DrawPosition(
        unit * Potential(), cells_.size(), [&](size_t c) { return cells_[c].potential; },
        [&](size_t c) { return cells_[c].begin; }, arena_.nearest.data(), Used());
    return arena_.index[m];
  }

  // Every vector's centre (cell) and squared distance to it.
  void Assignment(std::vector<uint32_t>& nearest, std::vector<float>& distances) const {
    nearest.assign(set_.size(), 0);
    distances.assign(set_.size(), 0.f);
    tbb::parallel_for(size_t(0), cells_.size(), [&](size_t c) {
      for (size_t m = cells_[c].begin; m < cells_[c].end; ++m) {
        if (arena_.nearest[m] == 0 && arena_.key[m] != 0) continue;  // moved on
        nearest[arena_.index[m]] = uint32_t(c);
        distances[arena_.index[m]] = arena_.nearest[m];
      }
    });
  }

  // The potential with each candidate (training vector indices) added, one at a time; keeps
  // who would move for Add.
  std::vector<double> Measure(const std::vector<size_t>& candidates) {
    const size_t trials = candidates.size();
    const size_t slots = (trials + 3) / 4 * 4;  // probes per cell, in fours; the extra never pass
    const int dimension = set_.dimension;
    // Per cell and trial: where the suffix that may move starts, and the candidate's probe.
    std::vector<size_t> from(cells_.size() * trials);
    std::vector<Sketch> probes(cells_.size() * slots);
    std::vector<float> gaps2(cells_.size() * slots, std::numeric_limits<float>::infinity());
    std::vector<size_t> lowest(cells_.size());  // of the cell's `from`
    tbb::parallel_for(size_t(0), cells_.size(), [&](size_t c) {
      const Cell& cell = cells_[c];
      lowest[c] = cell.end;
      for (size_t t = 0; t < trials; ++t) {
        const float gap2 = SquaredDistance(set_.Vector(candidates[t]), set_.Vector(cell.centre), nullptr, dimension);
        // Members with 4 |x - a|^2 < |c - a|^2 (with a margin for rounding) cannot move.
        size_t& first = from[c * trials + t];
        first = std::partition_point(arena_.key.begin() + cell.begin, arena_.key.begin() + cell.end,
                                     [gap2](float d) { return 4.f * d * (1.f + 1e-4f) < gap2; }) -
                arena_.key.begin();
        probes[c * slots + t] = MakeSketch(Projected(candidates[t]), Projected(cell.centre), axes_.count, gap2, true);
        gaps2[c * slots + t] = gap2;
        lowest[c] = std::min(lowest[c], first);
      }
    });
    chunks_.clear();
    for (size_t c = 0; c < cells_.size(); ++c)
      for (size_t begin = lowest[c]; begin < cells_[c].end; begin += kChunk)
        chunks_.push_back({c, begin, std::min(cells_[c].end, begin + kChunk), {}});
    std::vector<double> gains(chunks_.size() * trials, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, chunks_.size()), [&](const tbb::blocked_range<size_t>& range) {
      // First every member the bounds cannot rule out, then the measures, in one long run so
      // that prefetching keeps ahead of the scattered reads.
      std::vector<Passed> passed;
      for (size_t k = range.begin(); k != range.end(); ++k) {
        const Chunk& chunk = chunks_[k];
        const Run run{uint32_t(k),
                      chunk.begin,
                      chunk.end,
                      arena_.nearest.data(),
                      arena_.sketch.data(),
                      &from[chunk.cell * trials],
                      trials,
                      &probes[chunk.cell * slots],
                      &gaps2[chunk.cell * slots]};
        CollectPassed(run, avx2_, passed);
      }
      MeasurePassed(passed, candidates, gains);
    });
    std::vector<double> potentials(trials, Potential());
    for (size_t k = 0; k < chunks_.size(); ++k)
      for (size_t t = 0; t < trials; ++t) potentials[t] -= gains[k * trials + t];
    return potentials;
  }

  // Adds measured candidate `t`, training vector `centre`, as the next centre: the
  // vectors it is strictly nearer to than their centre move to a new cell.
  void Add(size_t t, uint32_t centre) {
    std::vector<Joiner> joiners;
    std::vector<size_t> changed;  // cells that lose members, ascending
    for (const Chunk& chunk : chunks_) {
      for (const Move& move : chunk.moves) {
        if (move.trial != t) continue;
        joiners.push_back({arena_.index[move.member], move.distance});
        arena_.nearest[move.member] = 0;
        if (changed.empty() || changed.back() != chunk.cell) changed.push_back(chunk.cell);
      }
    }
    tbb::parallel_for(size_t(0), changed.size(),
                      [&](size_t j) { cells_[changed[j]].potential = SumNearest(cells_[changed[j]]); });
    AddCell(std::move(joiners), centre);
  }

 private:
  static constexpr size_t kChunk = 2048;

  // A member that trial `trial` is strictly nearer to than its centre.
  struct Move {
    uint32_t member;
    uint32_t trial;
    float distance;
  };
  // A run of one cell measured by one task, and who would move.
  struct Chunk {
    size_t cell, begin, end;
    std::vector<Move> moves;
  };

  // Measures the `passed` members (by chunk, ascending) against their trials' candidates,
  // adding the potential each candidate gains to gains[chunk * trials + t] and recording who
  // would move. The vectors sit anywhere in the training set, so each is prefetched ahead.
  void MeasurePassed(const std::vector<Passed>& passed, const std::vector<size_t>& candidates,
                     std::vector<double>& gains) {
    constexpr size_t kAhead = 16;
    const int dimension = set_.dimension;
    const size_t trials = candidates.size();
    auto vector_of = [&](size_t j) { return set_.Vector(arena_.index[passed[j].member]); };
    for (size_t j = 0; j < std::min(kAhead, passed.size()); ++j) PrefetchVector(vector_of(j), dimension);
    for (size_t j = 0; j < passed.size(); ++j) {
      if (j + kAhead < passed.size()) PrefetchVector(vector_of(j + kAhead), dimension);
      const uint32_t m = passed[j].member;
      const uint32_t i = arena_.index[m];
      const float nearest = arena_.nearest[m];
      for (size_t t = 0; t < trials; ++t) {
        if (!(passed[j].trials >> t & 1)) continue;
        const float d = SquaredDistance(set_.Vector(i), set_.Vector(candidates[t]), nullptr, dimension, nearest);
        if (d < nearest) {
          gains[passed[j].chunk * trials + t] += nearest - d;
          chunks_[passed[j].chunk].moves.push_back({m, uint32_t(t), d});
        }
      }
    }
  }

  // Arena members in use: cells lie end to end in the arena.
  size_t Used() const { return cells_.empty() ? 0 : cells_.back().end; }

  const float* Projected(size_t vector) const { return projected_.data() + vector * axes_.count; }

  double SumNearest(const Cell& cell) const {
    return std::accumulate(arena_.nearest.begin() + cell.begin, arena_.nearest.begin() + cell.end, 0.0);
  }

  // Appends a cell for the centre cells_.size() holding `joiners`.
  void AddCell(std::vector<Joiner> joiners, uint32_t centre) {
    tbb::parallel_sort(joiners.begin(), joiners.end());  // a total order: the same result whatever the threads
    if (Used() + joiners.size() > arena_.index.size()) Compact();
    // Live members number at most the training vectors, and the arena holds half as many again.
    VT_CHECK(Used() + joiners.size() <= arena_.index.size(), Used(), " members + ", joiners.size(), " joiners");
    Cell cell;
    cell.centre = centre;
    cell.begin = Used();
    cell.end = cell.begin + joiners.size();
    tbb::parallel_for(size_t(0), joiners.size(), [&](size_t j) {
      const size_t m = cell.begin + j;
      const uint32_t i = joiners[j].index;
      arena_.index[m] = i;
      arena_.key[m] = arena_.nearest[m] = joiners[j].distance;
      arena_.sketch[m] = MakeSketch(Projected(i), Projected(centre), axes_.count, joiners[j].distance, false);
    });
    cell.potential = SumNearest(cell);
    cells_.push_back(cell);
  }

  // Drops the members that moved on, keeping every cell's order (cells stay in arena order).
  void Compact() {
    size_t to = 0;
    for (Cell& cell : cells_) {
      const size_t begin = to;
      for (size_t m = cell.begin; m < cell.end; ++m) {
        if (arena_.nearest[m] == 0 && arena_.key[m] != 0) continue;  // moved on (one on its centre stays)
        arena_.index[to] = arena_.index[m];
        arena_.key[to] = arena_.key[m];
        arena_.nearest[to] = arena_.nearest[m];
        arena_.sketch[to] = arena_.sketch[m];
        ++to;
      }
      cell.begin = begin;
      cell.end = to;
    }
    VT_CHECK(to <= set_.size() + cells_.size(), "compaction kept ", to, " members of ", set_.size(), " vectors");
  }

  const TrainingSet& set_;
  const bool avx2_;  // the sketch test may use AVX2
  PrincipalAxes axes_;
  HugePageVector<float> projected_;  // every training vector on the axes
  Arena arena_;
  std::vector<Cell> cells_;
  std::vector<Chunk> chunks_;  // the last measurement
};

// Greedy k-means++ from centre 0 = training vector `chosen` (already in `seeds`).
void Grow(const TrainingSet& set, BoundedSeeding& seeding, size_t chosen, std::mt19937_64& rng, int trials,
          Seeds& seeds) {
  std::vector<size_t> candidates;
  for (size_t k = 1; k < seeds.centres.size(); ++k) {
    if (seeding.Potential() <= 0) {  // fewer distinct vectors than codewords: duplicates are harmless
      chosen = (chosen + 1) % set.size();
      candidates.assign(1, chosen);
    } else {  // the state does not change between trials, so all are drawn first
      candidates.resize(trials);
      for (size_t& candidate : candidates) candidate = seeding.Sample(UniformUnit(rng));
    }
    const std::vector<double> potentials = seeding.Measure(candidates);
    const size_t best = std::min_element(potentials.begin(), potentials.end()) - potentials.begin();
    chosen = candidates[best];
    std::copy_n(set.Vector(chosen), set.dimension, seeds.centres.Codeword(k));
    seeding.Add(best, uint32_t(chosen));
  }
  seeding.Assignment(seeds.nearest, seeds.distances);
}

}  // namespace

Seeds SeedKMeansPlusPlus(const TrainingSet& set, size_t count, uint64_t seed, int trials, bool use_simd) {
  const size_t n = set.size();
  count = std::min(count, n);
  trials = std::max(trials, 1);
  Seeds seeds;
  seeds.centres = {set.dimension, std::vector<float>(count * set.dimension)};
  if (count == 0) return seeds;
  std::mt19937_64 rng(seed);
  const size_t chosen = rng() % n;
  std::copy_n(set.Vector(chosen), set.dimension, seeds.centres.Codeword(0));
  BoundedSeeding seeding(set, uint32_t(chosen), use_simd);
  Grow(set, seeding, chosen, rng, trials, seeds);
  // Weighted sets are seeded on plain distances; their own nearest centres are one assignment.
  if (set.weighted()) AssignNearest(seeds.centres, set, seeds.nearest, seeds.distances);
  return seeds;
}

}  // namespace voltree
