// Vectors to quantize: N vectors of D floats, row-major, with optional per-component weights.
// Colour vectors are 16 texels x (L*, a*, b*) = 48 floats; alpha vectors 16 floats.
#pragma once

#include <cstddef>
#include <vector>

#include "core/huge_page_allocator.h"

namespace voltree {

struct TrainingSet {
  int dimension = 0;
  HugePageVector<float> vectors;  // size() * dimension; read at random by GLA
  // Empty (plain L2) or one weight >= 0 per component: distance = sum w_i (x_i - c_i)^2.
  HugePageVector<float> weights;

  size_t size() const { return dimension > 0 ? vectors.size() / dimension : 0; }
  bool weighted() const { return !weights.empty(); }
  const float* Vector(size_t i) const { return vectors.data() + i * dimension; }
  const float* Weights(size_t i) const { return weighted() ? weights.data() + i * dimension : nullptr; }
  // Throws Error when the sizes disagree or a value is not finite.
  void Check() const;
};

// A codebook: K codewords of the training set's dimension, row-major.
struct Codebook {
  int dimension = 0;
  std::vector<float> codewords;

  size_t size() const { return dimension > 0 ? codewords.size() / dimension : 0; }
  const float* Codeword(size_t i) const { return codewords.data() + i * dimension; }
  float* Codeword(size_t i) { return codewords.data() + i * dimension; }
};

}  // namespace voltree
