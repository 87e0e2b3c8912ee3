#include "lod/pr_optimal_scale.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace voltree {

double PrScore(double precision, double recall) { return 1 - std::hypot(1 - precision, 1 - recall); }

const ScaleTrial& BestScaleTrial(const std::vector<ScaleTrial>& trials) {
  if (trials.empty()) Fail("lod: no scale trials to choose from");
  const ScaleTrial* best = &trials.front();
  for (const ScaleTrial& trial : trials) {
    const double score = PrScore(trial.precision, trial.recall), best_score = PrScore(best->precision, best->recall);
    if (score > best_score || (score == best_score && trial.area_scale < best->area_scale)) best = &trial;
  }
  return *best;
}

const ScaleTrial& NearestTrial(const std::vector<ScaleTrial>& trials, double area_scale) {
  if (trials.empty()) Fail("lod: no scale trials to choose from");
  const ScaleTrial* nearest = &trials.front();
  for (const ScaleTrial& trial : trials)
    if (std::abs(std::log(trial.area_scale / area_scale)) < std::abs(std::log(nearest->area_scale / area_scale)))
      nearest = &trial;
  return *nearest;
}

std::vector<double> CandidateAreaScales(double lambda) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: the kept fraction lambda = ", lambda, " is outside (0, 1]");
  std::vector<double> scales;
  for (int t = 0; t <= 13; ++t) scales.push_back(std::pow(lambda, -0.1 * t));
  if (lambda == 1) scales.resize(1);  // all the same
  return scales;
}

}  // namespace voltree
