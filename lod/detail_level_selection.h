// Neubert et al. 2011's detail level selection (sec. 2.5): instead of Cook's lambda(d) = (1 - d)^2,
// each tree model gets the smallest lambda whose rendering with the PR-optimal scale is at least
// as good as Cook's at that distance, Q(lambda_opt, s_opt) >= Q(lambda_Cook, s_Cook): the same
// quality with less geometry where the model allows it. Precomputed on sampled lambdas (10 in
// [0, 0.1), 10 in [0.1, 1.0]) and linearly interpolated between them.
#pragma once

#include <vector>

namespace voltree {

// One sampled geometry level: lambda, its PR-optimal area scale and the PR score Q there.
struct LevelSample {
  double lambda = 1;
  double area_scale = 1;
  double quality = 1;
};

// The paper's sample lambdas 0.01, ..., 0.09, 0.1, ..., 1.0, those >= min_lambda, ascending.
// Throws Error for min_lambda outside (0, 1].
std::vector<double> DetailLevelLambdas(double min_lambda);

// The smallest lambda at which the samples' quality, linearly interpolated in lambda, reaches
// `target`; the area scale there interpolated log-log (s_opt against lambda is smooth there, the
// paper's fig. 7). `samples` in any order. When none reaches the target, the best sample (on a
// tie the larger lambda). Throws Error when empty.
LevelSample QualityMatchedLevel(std::vector<LevelSample> samples, double target);

}  // namespace voltree
