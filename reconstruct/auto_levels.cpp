#include "reconstruct/auto_levels.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "reconstruct/grid.h"

namespace voltree {

namespace {

constexpr double kBytesPerBillboard = 2;

// The levels the photos fill (the finest is the first L with root / branching^L <= 1 pixel) and
// the root's texel in photo pixels.
struct PhotoLevels {
  int levels = 0;
  double root_texel_pixels = 0;
};

PhotoLevels LevelsThePhotosFill(const ReconstructInput& input, const ReconstructOptions& options) {
  if (input.views.empty()) Fail(input.source, ": no views to choose --levels auto from");
  const GridFrame frame = RootCube(input.bounds_min, input.bounds_max, options.margin, options.branching);
  const Eigen::Vector3d centre = frame.origin + Eigen::Vector3d::Constant(0.5 * frame.size);
  // Root texel size in photo pixels, per view; the median view decides.
  std::vector<double> root_texel_pixels;
  for (const View& view : input.views) {
    const double depth = view.pose.ToCamera(centre).z();
    if (!(depth > 0)) continue;
    const double focal = 0.5 * (view.camera.FocalX() + view.camera.FocalY());
    root_texel_pixels.push_back(focal * frame.size / options.texels / depth);
  }
  if (root_texel_pixels.empty()) Fail(input.source, ": no photo sees the scene bounds in front of it");
  std::nth_element(root_texel_pixels.begin(), root_texel_pixels.begin() + root_texel_pixels.size() / 2,
                   root_texel_pixels.end());
  const double root = root_texel_pixels[root_texel_pixels.size() / 2];
  const int finest = std::max(0, int(std::ceil(std::log(root) / std::log(double(options.branching)) - 1e-9)));
  const int largest = options.branching == 2 ? 16 : 10;  // 16-bit cell coordinates
  return {std::min(finest + 1, largest), root};
}

}  // namespace

int LevelsForPhotos(const ReconstructInput& input, const ReconstructOptions& options) {
  const auto [levels, root] = LevelsThePhotosFill(input, options);
  if (levels < 3)
    Fail(input.source, ": the photos (", input.views.front().camera.width, "x", input.views.front().camera.height,
         ") show the tree about ", int(std::lround(root * options.texels)), " pixels across: too small for even 3 ",
         "levels of ", options.texels, "x", options.texels, " texels (--levels auto gives ", levels,
         "); use larger photos or give --levels N");
  return levels;
}

int DeepeningCeiling(const ReconstructInput& input, const ReconstructOptions& options) {
  ReconstructOptions deeper = options;
  deeper.levels = std::max(options.levels, LevelsThePhotosFill(input, options).levels);
  const size_t available = options.memory_limit_bytes ? options.memory_limit_bytes : AvailableMemoryBytes();
  while (deeper.levels > options.levels && available && EstimateReconstructBytes(input, deeper) > available)
    --deeper.levels;
  return deeper.levels;
}

std::optional<DeepeningRule> DeepeningFor(const ReconstructInput& input, const ReconstructOptions& options) {
  if (options.deepen_within_bytes == 0 || options.auto_levels || input.views.empty()) return std::nullopt;
  DeepeningRule rule;
  rule.required = options.levels;
  rule.max_cells = size_t(double(options.deepen_within_bytes) / (kBytesPerBillboard * double(input.views.size())));
  return rule;
}

ReconstructOptions ResolveLevels(const ReconstructInput& input, const ReconstructOptions& options) {
  ReconstructOptions resolved = options;
  if (options.auto_levels) resolved.levels = LevelsForPhotos(input, options);
  return resolved;
}

}  // namespace voltree
