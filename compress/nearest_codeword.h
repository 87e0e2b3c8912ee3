// Nearest-codeword search for vector quantization, the inner loop of GLA and of encoding.
// Exact: returns what a brute-force scan returns (smallest distance, lowest index on ties), but
// prunes with (1) the previous assignment as a starting bound, (2) partial distance elimination,
// and (3) for unweighted distances, codewords sorted by norm with the bound
// (|x| - |c|)^2 <= |x - c|^2, scanning outward from |x| until it exceeds the best distance.
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
  // previous assignment), or any value >= size() for none.
  CodewordMatch Find(const float* vector, const float* weights, uint32_t hint) const;

 private:
  CodewordMatch FindWeighted(const float* vector, const float* weights, uint32_t hint) const;

  const Codebook& codebook_;
  std::vector<uint32_t> by_norm_;    // codeword indices sorted by norm, ties by index
  std::vector<float> sorted_norms_;  // norms in that order
};

// Reference implementation for tests and benchmarks.
CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights);

// Assigns every training vector to its nearest codeword, in parallel (TBB) and deterministically.
// `assignment` holds hints on entry (or is empty) and the result on exit; `distances` gets the
// squared distance of each vector to its codeword.
void AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances);

}  // namespace voltree
