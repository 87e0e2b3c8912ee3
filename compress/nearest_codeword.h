// Nearest-codeword search for vector quantization, the inner loop of GLA and of encoding. Exact:
// it returns what a brute-force scan returns (smallest distance, lowest index on ties). The
// distances to all codewords, plain or weighted, are one matrix product per block of vectors
// (compress/codeword_scores.h); the few codewords within its rounding bound of the best are then
// measured directly, and the measure decides.
#pragma once

#include <cstdint>
#include <vector>

#include "compress/training_set.h"

namespace voltree {

struct CodewordMatch {
  uint32_t index = 0;
  float distance = 0;  // squared, weighted when weights are given
};

// Reference implementation for tests and benchmarks.
CodewordMatch BruteForceNearest(const Codebook& codebook, const float* vector, const float* weights);

// Assigns every training vector to its nearest codeword, in parallel (TBB) and deterministically:
// `assignment` gets the codeword of each vector and `distances` its squared distance to it.
void AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances);

}  // namespace voltree
