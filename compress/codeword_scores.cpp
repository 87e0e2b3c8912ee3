#include "compress/codeword_scores.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cpu_features.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace voltree {
namespace {

constexpr int kRows = 4;  // vectors per tile of the portable kernel
constexpr int kPanel = CodewordScorer::kPanel;

// Everything a kernel needs: centred vectors (kBlock rows), the packed codebook, the output.
struct ScoreJob {
  const float* rows;
  int dimension;
  const float* panels;
  const float* norms2;
  size_t padded;  // scores per row
  float* scores;
  float* lowest;  // kBlock row minima
};

// Portable kernel: the same tiles in plain C++, which the compiler vectorizes for the baseline ISA.
void ScoreGeneric(const ScoreJob& job) {
  const int dimension = job.dimension;
  std::fill_n(job.lowest, CodewordScorer::kBlock, std::numeric_limits<float>::infinity());
  for (int r0 = 0; r0 < CodewordScorer::kBlock; r0 += kRows) {
    for (size_t p = 0; p * kPanel < job.padded; ++p) {
      const float* panel = job.panels + p * dimension * kPanel;
      float acc[kRows][kPanel] = {};
      for (int t = 0; t < dimension; ++t) {
        for (int r = 0; r < kRows; ++r) {
          const float x = job.rows[(r0 + r) * dimension + t];
          for (int l = 0; l < kPanel; ++l) acc[r][l] += x * panel[t * kPanel + l];
        }
      }
      for (int r = 0; r < kRows; ++r) {
        for (int l = 0; l < kPanel; ++l) {
          const float score = job.norms2[p * kPanel + l] - 2.f * acc[r][l];
          job.scores[(r0 + r) * job.padded + p * kPanel + l] = score;
          job.lowest[r0 + r] = std::min(job.lowest[r0 + r], score);
        }
      }
    }
  }
}

#if defined(__x86_64__)
// One row of a tile: score = |c|^2 - 2 x.c for 16 codewords, stored, and folded into the row minimum.
__attribute__((target("avx2,fma"))) inline void StoreScores(float* row, __m256 dot_low, __m256 dot_high,
                                                            __m256 norm2_low, __m256 norm2_high, __m256& lowest) {
  const __m256 minus_two = _mm256_set1_ps(-2.f);
  const __m256 low = _mm256_fmadd_ps(minus_two, dot_low, norm2_low);
  const __m256 high = _mm256_fmadd_ps(minus_two, dot_high, norm2_high);
  _mm256_storeu_ps(row, low);
  _mm256_storeu_ps(row + 8, high);
  lowest = _mm256_min_ps(lowest, _mm256_min_ps(low, high));
}

// AVX2 + FMA kernel: tiles of 6 vectors x 16 codewords, 12 accumulators; per component two
// codeword loads and six broadcasts feed twelve FMAs.
__attribute__((target("avx2,fma"))) void ScoreAvx2(const ScoreJob& job) {
  constexpr int kTile = 6;
  const int dimension = job.dimension;
  for (int r0 = 0; r0 < CodewordScorer::kBlock; r0 += kTile) {
    const float* x = job.rows + r0 * dimension;
    __m256 lowest[kTile];
    for (int r = 0; r < kTile; ++r) lowest[r] = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    for (size_t p = 0; p * kPanel < job.padded; ++p) {
      const float* panel = job.panels + p * dimension * kPanel;
      __m256 dot[kTile][2];
      for (int r = 0; r < kTile; ++r) dot[r][0] = dot[r][1] = _mm256_setzero_ps();
      for (int t = 0; t < dimension; ++t) {
        const __m256 low = _mm256_loadu_ps(panel + t * kPanel);
        const __m256 high = _mm256_loadu_ps(panel + t * kPanel + 8);
#pragma GCC unroll 6
        for (int r = 0; r < kTile; ++r) {
          const __m256 component = _mm256_broadcast_ss(x + r * dimension + t);
          dot[r][0] = _mm256_fmadd_ps(component, low, dot[r][0]);
          dot[r][1] = _mm256_fmadd_ps(component, high, dot[r][1]);
        }
      }
      const __m256 norm2_low = _mm256_loadu_ps(job.norms2 + p * kPanel);
      const __m256 norm2_high = _mm256_loadu_ps(job.norms2 + p * kPanel + 8);
      float* out = job.scores + r0 * job.padded + p * kPanel;
#pragma GCC unroll 6
      for (int r = 0; r < kTile; ++r)
        StoreScores(out + r * job.padded, dot[r][0], dot[r][1], norm2_low, norm2_high, lowest[r]);
    }
    for (int r = 0; r < kTile; ++r) {
      alignas(32) float lanes[8];
      _mm256_store_ps(lanes, lowest[r]);
      job.lowest[r0 + r] = *std::min_element(lanes, lanes + 8);
    }
  }
}

__attribute__((target("avx2,fma"))) size_t ShortlistAvx2(const float* row, size_t padded, float limit,
                                                         uint32_t* shortlist) {
  const __m256 bound = _mm256_set1_ps(limit);
  size_t count = 0;
  for (size_t base = 0; base < padded; base += 8) {
    unsigned mask = _mm256_movemask_ps(_mm256_cmp_ps(_mm256_loadu_ps(row + base), bound, _CMP_LE_OQ));
    for (; mask; mask &= mask - 1) shortlist[count++] = uint32_t(base + __builtin_ctz(mask));
  }
  return count;
}
#endif

}  // namespace

CodewordScorer::CodewordScorer(const Codebook& codebook, Distance distance, bool use_simd)
    : dimension_(codebook.dimension),
      product_dimension_(distance == Distance::kWeighted ? 2 * codebook.dimension : codebook.dimension),
      size_(codebook.size()),
      avx2_(use_simd && CpuHasAvx2Fma()) {
  const int d = dimension_;
  std::vector<double> sum(d, 0);
  for (size_t j = 0; j < size_; ++j)
    for (int t = 0; t < d; ++t) sum[t] += codebook.Codeword(j)[t];
  mean_.resize(d);
  for (int t = 0; t < d; ++t) mean_[t] = size_ ? static_cast<float>(sum[t] / double(size_)) : 0.f;
  const size_t padded = (size_ + kPanel - 1) / kPanel * kPanel;
  panels_.assign(padded * product_dimension_, 0.f);
  norms2_.assign(padded, std::numeric_limits<float>::infinity());
  for (size_t j = 0; j < size_; ++j) {
    float* column = panels_.data() + (j / kPanel) * product_dimension_ * kPanel + j % kPanel;
    double norm2 = 0;
    for (int t = 0; t < d; ++t) {
      const float centred = codebook.Codeword(j)[t] - mean_[t];
      if (weighted()) {
        column[t * kPanel] = -0.5f * centred * centred;
        column[(d + t) * kPanel] = centred;
      } else {
        column[t * kPanel] = centred;
      }
      norm2 += double(centred) * centred;
    }
    norms2_[j] = weighted() ? 0.f : static_cast<float>(norm2);
    max_norm_ = std::max(max_norm_, static_cast<float>(std::sqrt(norm2)));
  }
}

void CodewordScorer::CentreRows(const float* vectors, const float* weights, int count, float* rows,
                                float* tolerance) const {
  const int d = dimension_;
  std::fill_n(rows, size_t(kBlock) * product_dimension_, 0.f);
  for (int r = 0; r < count; ++r) {
    float* row = rows + size_t(r) * product_dimension_;
    double norm2 = 0;
    float largest_weight = 1;
    if (weighted()) largest_weight = *std::max_element(weights + size_t(r) * d, weights + size_t(r + 1) * d);
    for (int t = 0; t < d; ++t) {
      const float value = vectors[size_t(r) * d + t] - mean_[t];
      if (weighted()) {
        const float weight = weights[size_t(r) * d + t];
        row[t] = weight;
        row[d + t] = weight * value;
      } else {
        row[t] = value;
      }
      norm2 += double(value) * value;
    }
    // Each score is a sum of products whose magnitudes add up to at most w_max (|x| + |c|)^2;
    // its rounding error is below (terms) * 2^-24 times that, and SquaredDistance's is of the
    // same order. 3e-5 per 48 terms is 500 ulps of that scale: generous, and still far below the
    // gaps between real codewords.
    const float scale = static_cast<float>(std::sqrt(norm2)) + max_norm_;
    tolerance[r] = 3e-5f * std::max(1, product_dimension_ / 48) * largest_weight * scale * scale;
  }
}

void CodewordScorer::Score(const float* vectors, const float* weights, int count, float* scores, float* lowest,
                           float* tolerance) const {
  constexpr int kStackComponents = 128;  // rows of up to 128 products (voltree's are 16 to 96)
  float stack_rows[kBlock * kStackComponents];
  std::vector<float> heap_rows;
  float* rows = stack_rows;
  if (product_dimension_ > kStackComponents)
    heap_rows.resize(size_t(kBlock) * product_dimension_), rows = heap_rows.data();
  CentreRows(vectors, weights, count, rows, tolerance);
  const ScoreJob job{rows, product_dimension_, panels_.data(), norms2_.data(), padded_size(), scores, lowest};
#if defined(__x86_64__)
  if (avx2_) return ScoreAvx2(job);
#endif
  ScoreGeneric(job);
}

size_t CodewordScorer::Shortlist(const float* row, float limit, uint32_t* shortlist) const {
  // Pads score +infinity, so they never pass a finite limit.
#if defined(__x86_64__)
  if (avx2_) return ShortlistAvx2(row, padded_size(), limit, shortlist);
#endif
  size_t count = 0;
  for (size_t j = 0; j < size_; ++j)
    if (row[j] <= limit) shortlist[count++] = uint32_t(j);
  return count;
}

}  // namespace voltree
