// The leading principal axes of a training set: the unit eigenvectors of its covariance with the
// largest eigenvalues. Texture vectors are strongly correlated (16 texels of one patch), so a
// dozen axes carry most of their variance, and the projection on them is a cheap sketch of a
// vector that bounds dot products (see kmeans_plus_plus.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "compress/training_set.h"

namespace voltree {

struct PrincipalAxes {
  int count = 0;      // axes, largest variance first
  int dimension = 0;  // components of each
  // Component i of axis a at [i * count + a]: projecting walks the vector once and updates all
  // axes together, which vectorizes.
  std::vector<float> by_component;

  // Every vector of `set` on the axes: `count` floats per vector, into `projections`.
  void ProjectAll(const TrainingSet& set, float* projections) const;
};

// From an evenly strided sample of at most `sample` vectors (deterministic); `count` is clamped
// to the dimension. The weights of a weighted set are ignored.
PrincipalAxes FindPrincipalAxes(const TrainingSet& set, int count, size_t sample = 4096);

}  // namespace voltree
