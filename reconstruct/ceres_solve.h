// The same tomography as SART, solved as bounded least squares with Ceres: residual per ray
// (a_i x - b_i) / sqrt(|a_i|_1) (SART's weighting, so both reach the same minimiser), lower bound
// 0 on every sigma, optional Huber loss. For small volumes: it checks SART in the tests.
#pragma once

#include <vector>

#include "reconstruct/sart.h"
#include "reconstruct/tomography.h"

namespace voltree {

struct CeresSolveOptions {
  int iterations = 100;
  double huber = 0;  // > 0: Huber loss with this scale on the weighted residual
  int threads = 1;
  size_t max_cells = 200000;  // larger problems are refused: use SART

  void Check() const;  // throws OptionError naming the field
};

SolveReport SolveCeres(const TomographySystem& system, const CeresSolveOptions& options, std::vector<double>* x);

}  // namespace voltree
