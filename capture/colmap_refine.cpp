#include "capture/colmap_refine.h"

#include <cmath>
#include <string>
#include <vector>

#include "capture/colmap_binary.h"
#include "capture/colmap_runner.h"
#include "core/error.h"

namespace voltree {
namespace fs = std::filesystem;

void ModelRefinementOptions::Check() const {
  if (rounds < 0) FailOption("ModelRefinementOptions.rounds", "must be >= 0, got ", rounds);
  if (!(max_error >= 1 && std::isfinite(max_error)))
    FailOption("ModelRefinementOptions.max_error", "must be at least 1 (times the mean error), got ", max_error);
  if (!(min_tri_angle >= 0 && min_tri_angle < 90))
    FailOption("ModelRefinementOptions.min_tri_angle", "must be in [0, 90) degrees, got ", min_tri_angle);
}

RefinedModel RefineColmapModel(const fs::path& colmap, const fs::path& model_folder, const ColmapModel& model,
                               const fs::path& work_folder, const ModelRefinementOptions& options, Progress& progress) {
  options.Check();
  RefinedModel result{model, model_folder, 0, 0};
  const double mean_error = MeanReprojectionError(model);
  if (mean_error <= 0) return result;  // no observations to judge by
  const double max_error = options.max_error * mean_error;
  std::vector<std::string> keep_intrinsics;
  if (options.keep_intrinsics)
    keep_intrinsics = {"--BundleAdjustment.refine_focal_length", "0", "--BundleAdjustment.refine_principal_point", "0",
                       "--BundleAdjustment.refine_extra_params", "0"};
  for (int round = 1; round <= options.rounds; ++round) {
    const fs::path filtered = work_folder / Str(round, "_filtered");
    const fs::path adjusted = work_folder / Str(round);
    fs::create_directories(filtered);
    fs::create_directories(adjusted);
    const ChildResult filter =
        RunColmapStage(colmap, "point_filtering",
                       {"--input_path", result.folder.string(), "--output_path", filtered.string(),
                        "--max_reproj_error", Str(max_error), "--min_tri_angle", Str(options.min_tri_angle)},
                       work_folder / Str("point_filtering_", round, ".log"));
    std::vector<std::string> adjust = {"--input_path", filtered.string(), "--output_path", adjusted.string()};
    adjust.insert(adjust.end(), keep_intrinsics.begin(), keep_intrinsics.end());
    const ChildResult bundle =
        RunColmapStage(colmap, "bundle_adjuster", adjust, work_folder / Str("bundle_adjuster_", round, ".log"));
    result.seconds += filter.seconds + bundle.seconds;
    ColmapModel refined = ReadColmapModel(adjusted);
    if (refined.images.size() < result.model.images.size() || refined.points.empty()) {
      progress.Say("calibrate", Str("refinement round ", round, " would leave ", refined.images.size(), " of ",
                                    result.model.images.size(), " photos and ", refined.points.size(),
                                    " points; the model of round ", round - 1, " is kept"));
      return result;
    }
    progress.Say("calibrate", Str("refinement round ", round, ": ", refined.points.size(), " of ",
                                  result.model.points.size(), " points within ", std::round(max_error * 100) / 100,
                                  " px kept, mean error ", std::round(MeanReprojectionError(refined) * 1000) / 1000,
                                  " px (was ", std::round(MeanReprojectionError(result.model) * 1000) / 1000, " px)"));
    result.model = std::move(refined);
    result.folder = adjusted;
    result.rounds_taken = round;
  }
  return result;
}

}  // namespace voltree
