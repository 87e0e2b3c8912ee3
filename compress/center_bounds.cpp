#include "compress/center_bounds.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace voltree {
namespace {

// |R(v)| from |v|^2 and |Pv|^2, rounded up so the bound stays a bound despite float rounding.
float RestNorm(float norm2, float along2) { return std::sqrt(std::max(0.f, norm2 - along2) + 1e-4f * norm2); }

// For four probes c_0..c_3 with squared gaps gap2[0..3]: bit t set unless the vector sketched
// by `x` certainly cannot move to c_t. Each dot product sums four lanes (lane k: terms k, k + 4,
// ...) folded as (0 + 2) + (1 + 3), the same with SSE (the inner loop of the seeding) and without.
inline unsigned MayMove4(const Sketch& x, const Sketch* c, const float* gap2) {
#if defined(__SSE2__)
  const __m128 x0 = _mm_load_ps(x.terms), x1 = _mm_load_ps(x.terms + 4);
  const __m128 x2 = _mm_load_ps(x.terms + 8), x3 = _mm_load_ps(x.terms + 12);
  __m128 lanes[4];
  for (int t = 0; t < 4; ++t) {
    const float* p = c[t].terms;
    lanes[t] = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x0, _mm_load_ps(p)), _mm_mul_ps(x1, _mm_load_ps(p + 4))),
                                     _mm_mul_ps(x2, _mm_load_ps(p + 8))),
                          _mm_mul_ps(x3, _mm_load_ps(p + 12)));
  }
  // (l0 + l2) + (l1 + l3) of the four probes at once.
  const __m128 ab = _mm_add_ps(_mm_unpacklo_ps(lanes[0], lanes[1]), _mm_unpackhi_ps(lanes[0], lanes[1]));
  const __m128 cd = _mm_add_ps(_mm_unpacklo_ps(lanes[2], lanes[3]), _mm_unpackhi_ps(lanes[2], lanes[3]));
  const __m128 dots = _mm_add_ps(_mm_movelh_ps(ab, cd), _mm_movehl_ps(cd, ab));
  return unsigned(_mm_movemask_ps(_mm_cmpge_ps(_mm_add_ps(dots, dots), _mm_loadu_ps(gap2))));
#else
  unsigned mask = 0;
  for (int t = 0; t < 4; ++t) {
    float lanes[4];
    for (int k = 0; k < 4; ++k) lanes[k] = x.terms[k] * c[t].terms[k];
    for (int i = 4; i < 16; i += 4)
      for (int k = 0; k < 4; ++k) lanes[k] += x.terms[i + k] * c[t].terms[i + k];
    const float dot = (lanes[0] + lanes[2]) + (lanes[1] + lanes[3]);
    if (dot + dot >= gap2[t]) mask |= 1u << t;
  }
  return mask;
#endif
}

// The trials whose suffix holds arena member m (bit t: m >= first[t]).
inline uint64_t TrialsReaching(size_t m, const Run& run) {
  uint64_t reaching = 0;
  for (size_t t = 0; t < run.trials; ++t) reaching |= uint64_t(m >= run.first[t]) << t;
  return reaching;
}

// Two copies of one loop: the AVX2 one must be compiled for AVX2 as a whole to inline its test.
// Without branches on the data, which would mispredict: every member is written at the end of
// `passed`, which only grows past those that may move.
void CollectPassedBaseline(const Run& run, std::vector<Passed>& passed) {
  size_t count = passed.size();
  passed.resize(count + (run.end - run.begin));
  for (size_t m = run.begin; m < run.end; ++m) {
    uint64_t may_move = run.nearest[m] > 0 ? TrialsReaching(m, run) : 0;  // 0: moved on, or on its centre
    for (size_t t = 0; t < run.trials; t += 4)
      may_move &= ~(uint64_t(~MayMove4(run.sketches[m], run.probes + t, run.gaps2 + t) & 15u) << t);
    passed[count] = {run.chunk, uint32_t(m), may_move};
    count += may_move != 0;
  }
  passed.resize(count);
}

#if defined(__x86_64__)
// MayMove4 with AVX2: two 8-lane halves per sketch, FMA, and a horizontal-add reduction.
__attribute__((target("avx2,fma"))) inline unsigned MayMove4Avx2(const Sketch& x, const Sketch* c, const float* gap2) {
  const __m256 low = _mm256_load_ps(x.terms), high = _mm256_load_ps(x.terms + 8);
  __m256 products[4];
  for (int t = 0; t < 4; ++t)
    products[t] = _mm256_fmadd_ps(high, _mm256_load_ps(c[t].terms + 8), _mm256_mul_ps(low, _mm256_load_ps(c[t].terms)));
  const __m256 sums =
      _mm256_hadd_ps(_mm256_hadd_ps(products[0], products[1]), _mm256_hadd_ps(products[2], products[3]));
  const __m128 dots = _mm_add_ps(_mm256_castps256_ps128(sums), _mm256_extractf128_ps(sums, 1));
  return unsigned(_mm_movemask_ps(_mm_cmpge_ps(_mm_add_ps(dots, dots), _mm_loadu_ps(gap2))));
}

__attribute__((target("avx2,fma"))) void CollectPassedAvx2(const Run& run, std::vector<Passed>& passed) {
  size_t count = passed.size();
  passed.resize(count + (run.end - run.begin));
  for (size_t m = run.begin; m < run.end; ++m) {
    uint64_t may_move = run.nearest[m] > 0 ? TrialsReaching(m, run) : 0;
    for (size_t t = 0; t < run.trials; t += 4)
      may_move &= ~(uint64_t(~MayMove4Avx2(run.sketches[m], run.probes + t, run.gaps2 + t) & 15u) << t);
    passed[count] = {run.chunk, uint32_t(m), may_move};
    count += may_move != 0;
  }
  passed.resize(count);
}
#endif

}  // namespace

Sketch MakeSketch(const float* projected_x, const float* projected_a, int axes, float norm2, bool probe) {
  Sketch sketch{};
  float along2 = 0;
  for (int i = 0; i < axes; ++i) {
    sketch.terms[i] = projected_x[i] - projected_a[i];
    along2 += sketch.terms[i] * sketch.terms[i];
  }
  sketch.terms[kSketchAxes] = RestNorm(norm2, along2);
  sketch.terms[kSketchAxes + 1] = (probe ? 1e-3f : 1.f) * std::sqrt(norm2);
  return sketch;
}

void CollectPassed(const Run& run, bool avx2, std::vector<Passed>& passed) {
#if defined(__x86_64__)
  if (avx2) return CollectPassedAvx2(run, passed);
#endif
  (void)avx2;
  CollectPassedBaseline(run, passed);
}

}  // namespace voltree
