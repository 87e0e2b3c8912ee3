// Nearest-codeword search for vector quantization, the inner loop of GLA and of encoding. Exact:
// it returns what a brute-force scan returns (smallest distance, lowest index on ties).
//  - Plain L2: the distances to all codewords are one matrix product per block of vectors
//    (compress/codeword_scores.h); the few codewords within its rounding bound of the best are
//    then measured directly, and the measure decides.
//  - Weighted L2 (each vector its own weights, so no shared product): a scan from the previous
//    codeword of the vector, with partial distance elimination.
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

// Assigns every training vector to its nearest codeword, in parallel (TBB) and deterministically.
// `assignment` holds hints on entry (or is empty; only the weighted scan uses them) and the result
// on exit; `distances` gets the squared distance of each vector to its codeword.
void AssignNearest(const Codebook& codebook, const TrainingSet& set, std::vector<uint32_t>& assignment,
                   std::vector<float>& distances);

}  // namespace voltree
