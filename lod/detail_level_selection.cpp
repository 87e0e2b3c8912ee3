#include "lod/detail_level_selection.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace voltree {

std::vector<double> DetailLevelLambdas(double min_lambda) {
  if (!(min_lambda > 0 && min_lambda <= 1)) Fail("lod: the smallest lambda ", min_lambda, " is outside (0, 1]");
  std::vector<double> lambdas;
  for (int i = 1; i <= 9; ++i) lambdas.push_back(0.01 * i);
  for (int i = 1; i <= 10; ++i) lambdas.push_back(0.1 * i);
  std::erase_if(lambdas, [min_lambda](double lambda) { return lambda < min_lambda - 1e-12; });
  return lambdas;
}

LevelSample QualityMatchedLevel(std::vector<LevelSample> samples, double target) {
  if (samples.empty()) Fail("lod: no sampled geometry levels to choose from");
  std::sort(samples.begin(), samples.end(),
            [](const LevelSample& a, const LevelSample& b) { return a.lambda < b.lambda; });
  if (samples.front().quality >= target) return samples.front();
  for (size_t k = 1; k < samples.size(); ++k) {
    const LevelSample &lo = samples[k - 1], &hi = samples[k];
    if (hi.quality < target) continue;
    if (hi.lambda == lo.lambda) return hi;
    const double t = (target - lo.quality) / (hi.quality - lo.quality);  // hi > target > lo
    LevelSample matched;
    matched.lambda = lo.lambda + t * (hi.lambda - lo.lambda);
    matched.area_scale = std::exp(std::log(lo.area_scale) + (std::log(matched.lambda) - std::log(lo.lambda)) /
                                                                (std::log(hi.lambda) - std::log(lo.lambda)) *
                                                                (std::log(hi.area_scale) - std::log(lo.area_scale)));
    matched.quality = target;
    return matched;
  }
  return *std::max_element(samples.begin(), samples.end(), [](const LevelSample& a, const LevelSample& b) {
    return a.quality < b.quality || (a.quality == b.quality && a.lambda < b.lambda);
  });
}

}  // namespace voltree
