#include "reconstruct/sart.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace voltree {

double RmsResidual(const TomographySystem& system, const std::vector<double>& x) {
  const auto chunks = ViewChunks(system.view_count());
  std::vector<double> sums(chunks.size(), 0.0);
  std::vector<size_t> counts(chunks.size(), 0);
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t k) {
    std::vector<uint32_t> sc;
    std::vector<float> sl;
    for (size_t v = chunks[k].first; v < chunks[k].second; ++v)
      system.ForEachRay(v, &sc, &sl, [&](const uint32_t* c, const float* l, size_t n, float b) {
        double dot = 0;
        for (size_t i = 0; i < n; ++i) dot += double(l[i]) * x[c[i]];
        sums[k] += (b - dot) * (b - dot);
        ++counts[k];
      });
  });
  double sum = 0;
  size_t count = 0;
  for (size_t k = 0; k < chunks.size(); ++k) {
    sum += sums[k];
    count += counts[k];
  }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

SolveReport SolveSart(const TomographySystem& system, const SartOptions& options, std::vector<double>* x) {
  const size_t n_cells = system.cell_count();
  const auto chunks = ViewChunks(system.view_count());
  std::vector<std::vector<double>> partial(chunks.size(), std::vector<double>(n_cells));
  const std::vector<double>& column_sums = system.column_sums();
  SolveReport report;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    tbb::parallel_for(size_t(0), chunks.size(), [&](size_t k) {
      std::vector<double>& acc = partial[k];
      std::fill(acc.begin(), acc.end(), 0.0);
      std::vector<uint32_t> sc;
      std::vector<float> sl;
      for (size_t v = chunks[k].first; v < chunks[k].second; ++v)
        system.ForEachRay(v, &sc, &sl, [&](const uint32_t* c, const float* l, size_t n, float b) {
          double dot = 0, row_sum = 0;
          for (size_t i = 0; i < n; ++i) {
            dot += double(l[i]) * (*x)[c[i]];
            row_sum += l[i];
          }
          const double r = (b - dot) / row_sum;
          for (size_t i = 0; i < n; ++i) acc[c[i]] += double(l[i]) * r;
        });
    });
    tbb::parallel_for(size_t(0), n_cells, [&](size_t c) {
      if (column_sums[c] <= 0) return;
      double update = 0;
      for (size_t k = 0; k < chunks.size(); ++k) update += partial[k][c];
      (*x)[c] = std::max(0.0, (*x)[c] + options.relaxation * update / column_sums[c]);
    });
    report.iterations = iteration + 1;
  }
  report.rms_residual = RmsResidual(system, *x);
  return report;
}

void SartOptions::Check() const {
  if (iterations < 1) FailOption("SartOptions.iterations", "must be at least 1, got ", iterations);
  if (!(relaxation > 0 && relaxation < 2)) FailOption("SartOptions.relaxation", "must be in (0, 2), got ", relaxation);
}

}  // namespace voltree
