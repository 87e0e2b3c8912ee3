// Nearest-codeword search for vector quantization, the inner loop of GLA and of encoding.
// Exact: returns what a brute-force scan returns (smallest distance, lowest index on ties), but
// prunes with (1) the previous assignment as a starting bound, (2) partial distance elimination,
// and (3) for unweighted distances, codewords sorted by norm with the bound
// (|x| - |c|)^2 <= |x - c|^2, scanning outward from |x| until it exceeds the best distance.
// Across Lloyd iterations, AssignmentBounds (Hamerly 2010) skips the search altogether for the
// vectors whose codeword provably stays the nearest.
#pragma once

#include <cstdint>
#include <vector>

#include "compress/training_set.h"

namespace voltree {

struct CodewordMatch {
  uint32_t index = 0;
  float distance = 0;  // squared, weighted when weights are given
};

class NearestCodewordSearch {
 public:
  explicit NearestCodewordSearch(const Codebook& codebook);

  // `weights` may be null (plain L2). `hint` is a codeword index to try first (e.g. the
  // previous assignment), or any value >= size() for none. For plain L2, `second` (when not
  // null) receives a lower bound on the squared distance to every other codeword (infinity when
  // there is none).
  CodewordMatch Find(const float* vector, const float* weights, uint32_t hint, float* second = nullptr) const;

 private:
  CodewordMatch FindWeighted(const float* vector, const float* weights, uint32_t hint) const;

  const Codebook& codebook_;
  std::vector<uint32_t> by_norm_;    // codeword indices sorted by norm, ties by index
  std::vector<float> sorted_norms_;  // norms in that order
};

// Reference implementation for tests and benchmarks.
CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights);

// What one assignment knows for the next one, after the codewords have moved (Hamerly 2010):
// per vector, an upper bound on the distance (not squared) to its codeword and a lower bound on
// the distance to every other codeword, and the codewords they were measured against. When the
// upper bound plus its codeword's move stays below the lower bound minus the largest other move,
// the vector keeps its codeword without a search. Plain L2 only (weighted sets are searched).
struct AssignmentBounds {
  Codebook codebook;  // the codewords of the previous assignment
  std::vector<float> upper, lower;
};

// Assigns every training vector to its nearest codeword, in parallel (TBB) and deterministically.
// `assignment` holds hints on entry (or is empty) and the result on exit; `distances` gets the
// squared distance of each vector to its codeword. `bounds` (optional, kept by the caller between
// calls on the same set) makes later calls skip most searches; the result is the same. Returns how
// many vectors were searched (the others kept their codeword by the bounds).
size_t AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances, AssignmentBounds* bounds = nullptr);

}  // namespace voltree
