#include "capture/matte/options.h"

#include <algorithm>

#include "core/error.h"

namespace voltree {

RefineMethod ParseRefineMethod(const std::string& name) {
  if (name == "guided") return RefineMethod::kGuided;
  if (name == "infoflow") return RefineMethod::kInfoFlow;
  if (name == "none") return RefineMethod::kNone;
  Fail("unknown matting method '", name, "'; expected guided, infoflow or none");
}

std::string RefineMethodName(RefineMethod method) {
  switch (method) {
    case RefineMethod::kGuided:
      return "guided";
    case RefineMethod::kInfoFlow:
      return "infoflow";
    case RefineMethod::kNone:
      return "none";
  }
  return "?";
}

void MatteOptions::Check() const {
  if (horizon > 1.0) FailOption("MatteOptions.horizon", "must be a fraction of the height in [0, 1], got ", horizon);
  if (band_radius < 0 || band_radius > 64)
    FailOption("MatteOptions.band_radius", "must be in [0, 64], got ", band_radius);
  if (!(sky_seed_rows > 0.0 && sky_seed_rows <= 0.5))
    FailOption("MatteOptions.sky_seed_rows", "must be in (0, 0.5], got ", sky_seed_rows);
  if (!(max_sky_sigma > 0.0)) FailOption("MatteOptions.max_sky_sigma", "must be positive, got ", max_sky_sigma);
  if (!(sky_tolerance > 0.0)) FailOption("MatteOptions.sky_tolerance", "must be positive, got ", sky_tolerance);
  if (!(leaf_search > 0.0 && leaf_search <= 0.5))
    FailOption("MatteOptions.leaf_search", "must be in (0, 0.5], got ", leaf_search);
  if (!(leaf_purity > 0.0 && leaf_purity <= 1.0))
    FailOption("MatteOptions.leaf_purity", "must be in (0, 1], got ", leaf_purity);
  if (!(gap_distance > 0.0)) FailOption("MatteOptions.gap_distance", "must be positive, got ", gap_distance);
  if (grabcut_max_side < 64) FailOption("MatteOptions.grabcut_max_side", "must be at least 64, got ", grabcut_max_side);
  if (guided_radius < 1 || guided_radius > 32)
    FailOption("MatteOptions.guided_radius", "must be in [1, 32], got ", guided_radius);
  if (!(guided_epsilon > 0.0)) FailOption("MatteOptions.guided_epsilon", "must be positive, got ", guided_epsilon);
  if (infoflow_tile < 32) FailOption("MatteOptions.infoflow_tile", "must be at least 32, got ", infoflow_tile);
}

int MatteOptions::BandRadius(int width, int height) const {
  return band_radius > 0 ? band_radius : std::max(1, std::min(width, height) / 256);
}

}  // namespace voltree
