// Squared (optionally weighted) L2 distance with a fixed summation order, so that a partial
// distance search and a brute-force search compute bit-identical values: eight independent
// lanes (vectorizable without -ffast-math), folded in a fixed order.
#pragma once

#include <limits>

namespace voltree {

// Asks for the cache lines of a vector ahead of its use, for loops over scattered vectors.
inline void PrefetchVector(const float* vector, int dimension) {
  const char* bytes = reinterpret_cast<const char*>(vector);
  for (int offset = 0; offset < int(sizeof(float)) * dimension; offset += 64) __builtin_prefetch(bytes + offset);
}

// Components are processed in chunks of 16; after each chunk the running sum is compared with
// `bound` and the search gives up (returns a value > bound) as soon as it is exceeded: partial
// distance elimination. With bound = infinity this is the full distance.
inline float SquaredDistance(const float* x, const float* c, const float* w, int dimension,
                             float bound = std::numeric_limits<float>::infinity()) {
  float lanes[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  auto fold = [&lanes] {
    return ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3])) + ((lanes[4] + lanes[5]) + (lanes[6] + lanes[7]));
  };
  int i = 0;
  while (i < dimension) {
    const int end = i + 16 <= dimension ? i + 16 : dimension;
    for (; i + 8 <= end; i += 8) {
      for (int k = 0; k < 8; ++k) {
        const float d = x[i + k] - c[i + k];
        lanes[k] += (w ? w[i + k] : 1.f) * d * d;
      }
    }
    for (int k = 0; i < end; ++i, ++k) {  // tail of a dimension that is not a multiple of 8
      const float d = x[i] - c[i];
      lanes[k] += (w ? w[i] : 1.f) * d * d;
    }
    if (i < dimension) {
      const float partial = fold();
      if (partial > bound) return partial;
    }
  }
  return fold();
}

}  // namespace voltree
