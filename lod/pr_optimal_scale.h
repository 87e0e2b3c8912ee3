// Neubert et al. 2011's model-dependent scaling: instead of Cook's s = 1 / lambda, the area scale
// of the surviving leaves is the one whose render's precision and recall of covered pixels
// (against the full model) lie nearest to the ideal P = R = 1 (their eq. 3); the quality of a
// render is Q = 1 - |(1 - P, 1 - R)| (eq. 4). Found in a preprocessing step by trying candidate
// scales.
#pragma once

#include <vector>

namespace voltree {

// Neubert's Q: 1 at P = R = 1, 1 - sqrt(2) at P = R = 0.
double PrScore(double precision, double recall);

struct ScaleTrial {
  double area_scale = 1;
  double precision = 1;
  double recall = 1;
};

// The trial with the highest PrScore (eq. 3); on a tie the smallest scale. Throws Error when empty.
const ScaleTrial& BestScaleTrial(const std::vector<ScaleTrial>& trials);

// The trial whose scale is nearest `area_scale` in ratio (e.g. Cook's 1 / lambda among the
// candidates). Throws Error when empty.
const ScaleTrial& NearestTrial(const std::vector<ScaleTrial>& trials, double area_scale);

// The candidate area scales tried for one lambda: lambda^-t for t = 0, 0.1, ..., 1.3, from no
// scaling through Cook's 1 / lambda (t = 1) to beyond it.
std::vector<double> CandidateAreaScales(double lambda);

}  // namespace voltree
