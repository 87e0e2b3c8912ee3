#include "compress/principal_axes.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace voltree {

void PrincipalAxes::ProjectAll(const TrainingSet& set, float* projections) const {
  const size_t n = set.size();
  const Eigen::Map<const Eigen::MatrixXf> axes(by_component.data(), count, dimension);
  // Fixed chunks, so the products (and their rounding) do not depend on the threads.
  constexpr size_t kChunk = 4096;
  tbb::parallel_for(size_t(0), (n + kChunk - 1) / kChunk, [&](size_t chunk) {
    const size_t first = chunk * kChunk, columns = std::min(kChunk, n - first);
    const Eigen::Map<const Eigen::MatrixXf> vectors(set.Vector(first), dimension, Eigen::Index(columns));
    Eigen::Map<Eigen::MatrixXf>(projections + first * count, count, Eigen::Index(columns)).noalias() = axes * vectors;
  });
}

PrincipalAxes FindPrincipalAxes(const TrainingSet& set, int count, size_t sample) {
  const int d = set.dimension;
  PrincipalAxes result;
  result.dimension = d;
  result.count = std::clamp(count, 0, d);
  const size_t n = set.size();
  if (n == 0 || result.count == 0) {
    result.count = 0;
    return result;
  }
  const size_t stride = std::max<size_t>(1, n / std::max<size_t>(1, sample));
  const size_t m = (n + stride - 1) / stride;
  Eigen::MatrixXd centred(d, m);
  for (size_t j = 0; j < m; ++j)
    for (int i = 0; i < d; ++i) centred(i, j) = set.Vector(j * stride)[i];
  const Eigen::VectorXd mean = centred.rowwise().mean();
  centred.colwise() -= mean;
  const Eigen::MatrixXd covariance = centred * centred.transpose() / double(m);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);  // eigenvalues ascending
  result.by_component.resize(size_t(result.count) * d);
  for (int a = 0; a < result.count; ++a)
    for (int i = 0; i < d; ++i)
      result.by_component[size_t(i) * result.count + a] = float(solver.eigenvectors()(i, d - 1 - a));
  return result;
}

}  // namespace voltree
