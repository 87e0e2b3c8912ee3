#include "capture/matte_options.h"

#include "core/error.h"

namespace voltree {

RefineMethod ParseRefineMethod(const std::string& name) {
  if (name == "guided") return RefineMethod::kGuided;
  if (name == "infoflow") return RefineMethod::kInfoFlow;
  if (name == "none") return RefineMethod::kNone;
  Fail("--refine: unknown method '", name, "'; expected guided, infoflow or none");
}

std::string RefineMethodName(RefineMethod method) {
  switch (method) {
    case RefineMethod::kGuided: return "guided";
    case RefineMethod::kInfoFlow: return "infoflow";
    case RefineMethod::kNone: return "none";
  }
  return "?";
}

void MatteOptions::Check() const {
  if (horizon > 1.0) Fail("matte option horizon: ", horizon, " is not a fraction of the height in [0, 1]");
  if (band_radius < 0 || band_radius > 64) Fail("matte option band_radius: ", band_radius, " not in [0, 64]");
  if (!(sky_seed_rows > 0.0 && sky_seed_rows <= 0.5))
    Fail("matte option sky_seed_rows: ", sky_seed_rows, " not in (0, 0.5]");
  if (!(max_sky_sigma > 0.0)) Fail("matte option max_sky_sigma: ", max_sky_sigma, " must be positive");
  if (!(sky_tolerance > 0.0)) Fail("matte option sky_tolerance: ", sky_tolerance, " must be positive");
  if (!(leaf_search > 0.0 && leaf_search <= 0.5)) Fail("matte option leaf_search: ", leaf_search, " not in (0, 0.5]");
  if (!(leaf_purity > 0.0 && leaf_purity <= 1.0)) Fail("matte option leaf_purity: ", leaf_purity, " not in (0, 1]");
  if (grabcut_max_side < 64) Fail("matte option grabcut_max_side: ", grabcut_max_side, " below 64");
  if (guided_radius < 1 || guided_radius > 32) Fail("matte option guided_radius: ", guided_radius, " not in [1, 32]");
  if (!(guided_epsilon > 0.0)) Fail("matte option guided_epsilon: ", guided_epsilon, " must be positive");
  if (infoflow_tile < 32) Fail("matte option infoflow_tile: ", infoflow_tile, " below 32");
}

}  // namespace voltree
