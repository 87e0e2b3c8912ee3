#include "lod/mesh_lod_options.h"

#include "core/error.h"

namespace voltree {
namespace {

constexpr std::pair<MeshLodMethod, const char*> kNames[] = {{MeshLodMethod::kMesh, "mesh"},
                                                            {MeshLodMethod::kPoints, "points"},
                                                            {MeshLodMethod::kEllipsoids, "ellipsoids"},
                                                            {MeshLodMethod::kCook, "cook"},
                                                            {MeshLodMethod::kNeubert, "neubert"}};

}  // namespace

std::optional<MeshLodMethod> MeshLodMethodFromName(std::string_view name) {
  for (const auto& [method, text] : kNames)
    if (name == text) return method;
  return std::nullopt;
}

const char* MeshLodMethodName(MeshLodMethod method) {
  for (const auto& [m, text] : kNames)
    if (m == method) return text;
  return "?";
}

std::string MeshLodMethodList() {
  std::string list;
  for (const auto& [method, text] : kNames) list += Str(list.empty() ? "" : ", ", text);
  return list;
}

void MeshLodOptions::Check() const {
  if (!(full_pixels >= 8)) FailOption("MeshLodOptions.full_pixels", "is ", full_pixels, ", not >= 8 pixels");
  if (!(min_lambda > 0 && min_lambda <= 1))
    FailOption("MeshLodOptions.min_lambda", "is ", min_lambda, ", outside (0, 1]: it is a fraction of the leaves");
  if (steps_per_octave < 1 || steps_per_octave > 16)
    FailOption("MeshLodOptions.steps_per_octave", "is ", steps_per_octave, ", not in 1..16");
  if (!(ellipsoid_scale > 0)) FailOption("MeshLodOptions.ellipsoid_scale", "is ", ellipsoid_scale, ", not > 0");
  if (supersample < 1 || supersample > 8) FailOption("MeshLodOptions.supersample", "is ", supersample, ", not in 1..8");
  points.Check();
  ellipsoids.Check();
  occlusion.Check();
}

}  // namespace voltree
