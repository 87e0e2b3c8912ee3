#include "lod/occlusion_factor.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

void OcclusionOptions::Check() const {
  if (samples < 1 || samples > 4096) FailOption("OcclusionOptions.samples", "is ", samples, ", not in 1..4096");
  if (!(min_factor > 0 && min_factor <= 1))
    FailOption("OcclusionOptions.min_factor", "is ", min_factor, ", outside (0, 1]");
  if (!(depth_bias >= 0 && depth_bias <= 1))
    FailOption("OcclusionOptions.depth_bias", "is ", depth_bias, ", outside [0, 1] (a fraction of the tree's height)");
  if (!(fall > 0 && fall <= 1)) FailOption("OcclusionOptions.fall", "is ", fall, ", outside (0, 1]");
}

Visibility VisibleFraction(const std::vector<CrownSample>& samples, const InstanceTransform& transform, double height,
                           const FrameDepth& depth, const OcclusionOptions& options) {
  const Eigen::Vector3d eye = transform.ToAsset(depth.view().pose.Center());
  const double bias = options.depth_bias * height * transform.scale;
  Visibility result;
  int visible = 0;
  for (const CrownSample& sample : samples) {
    const Eigen::Vector3d point = sample.point.cast<double>();
    if (sample.normal.cast<double>().dot(eye - point) <= 0) continue;
    ++result.tested;
    visible += depth.Visible(transform.ToWorld(point), bias);
  }
  if (result.tested > 0) result.fraction = double(visible) / result.tested;
  return result;
}

double SmoothedVisibility(std::optional<double> previous, double measured, double fall) {
  if (!previous || measured >= *previous) return measured;
  return *previous + fall * (measured - *previous);
}

double OccludedLambda(double lambda, double visible, double min_factor) {
  if (!(lambda > 0 && lambda <= 1)) Fail("lod: lambda ", lambda, " is outside (0, 1]");
  return lambda * std::clamp(visible, min_factor, 1.0);
}

}  // namespace voltree
