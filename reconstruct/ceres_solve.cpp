#include "reconstruct/ceres_solve.h"

#include <ceres/ceres.h>

#include <cmath>

#include "core/error.h"

namespace voltree {
namespace {

// r = w * (sum_k l_k x_k - b), one parameter block of size 1 per crossed cell.
class RayCost : public ceres::CostFunction {
 public:
  RayCost(std::vector<double> weighted_lengths, double weighted_b)
      : lengths_(std::move(weighted_lengths)), b_(weighted_b) {
    set_num_residuals(1);
    for (size_t i = 0; i < lengths_.size(); ++i) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    double dot = 0;
    for (size_t i = 0; i < lengths_.size(); ++i) dot += lengths_[i] * parameters[i][0];
    residuals[0] = dot - b_;
    if (jacobians)
      for (size_t i = 0; i < lengths_.size(); ++i)
        if (jacobians[i]) jacobians[i][0] = lengths_[i];
    return true;
  }

 private:
  std::vector<double> lengths_;
  double b_;
};

}  // namespace

SolveReport SolveCeres(const TomographySystem& system, const CeresSolveOptions& options, std::vector<double>* x) {
  if (system.cell_count() > options.max_cells)
    Fail("the Ceres solver is for small volumes: this level has ", system.cell_count(), " cells (limit ",
         options.max_cells, "); use --solver sart or fewer --levels");
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (size_t c = 0; c < x->size(); ++c) problem.AddParameterBlock(&(*x)[c], 1);
  std::vector<uint32_t> sc;
  std::vector<float> sl;
  std::vector<double*> blocks;
  for (size_t v = 0; v < system.view_count(); ++v)
    system.ForEachRay(v, &sc, &sl, [&](const uint32_t* c, const float* l, size_t n, float b) {
      double row_sum = 0;
      for (size_t i = 0; i < n; ++i) row_sum += l[i];
      const double w = 1.0 / std::sqrt(row_sum);
      std::vector<double> lengths(n);
      blocks.resize(n);
      for (size_t i = 0; i < n; ++i) {
        lengths[i] = w * l[i];
        blocks[i] = &(*x)[c[i]];
      }
      ceres::LossFunction* loss = options.huber > 0 ? new ceres::HuberLoss(options.huber) : nullptr;
      problem.AddResidualBlock(new RayCost(std::move(lengths), w * b), loss, blocks);
    });
  for (size_t c = 0; c < x->size(); ++c)
    if (system.column_sums()[c] > 0)  // crossed by some ray
      problem.SetParameterLowerBound(&(*x)[c], 0, 0.0);
    else
      problem.SetParameterBlockConstant(&(*x)[c]);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::CGNR;
  solver_options.max_num_iterations = options.iterations;
  solver_options.num_threads = options.threads;
  solver_options.function_tolerance = 1e-12;
  solver_options.gradient_tolerance = 1e-14;
  solver_options.parameter_tolerance = 1e-12;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  if (!summary.IsSolutionUsable()) Fail("the Ceres solver failed: ", summary.message);
  SolveReport report;
  report.iterations = int(summary.iterations.size());
  report.rms_residual = RmsResidual(system, *x);
  return report;
}

void CeresSolveOptions::Check() const {
  if (iterations < 1) FailOption("CeresSolveOptions.iterations", "must be at least 1, got ", iterations);
  if (!(huber >= 0)) FailOption("CeresSolveOptions.huber", "must be >= 0, got ", huber);
  if (threads < 1) FailOption("CeresSolveOptions.threads", "must be at least 1, got ", threads);
}

}  // namespace voltree
