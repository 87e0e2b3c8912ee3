#include "samples/studio_options.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace voltree {

BackdropStyle BackdropStyleFromName(const std::string& name) {
  if (name == "realistic") return BackdropStyle::kRealistic;
  if (name == "plain") return BackdropStyle::kPlain;
  Fail("unknown backdrop '", name, "'; expected realistic or plain");
}

const char* BackdropStyleName(BackdropStyle style) {
  return style == BackdropStyle::kRealistic ? "realistic" : "plain";
}

void StudioOptions::Check() const {
  if (views < 1) FailOption("StudioOptions.views", "must be at least 1, got ", views);
  if (rings < 1 || rings > views) FailOption("StudioOptions.rings", "must be in 1..views (", views, "), got ", rings);
  if (held_out < 0) FailOption("StudioOptions.held_out", "must not be negative, got ", held_out);
  if (views > 999 || held_out > 999)
    FailOption(views > 999 ? "StudioOptions.views" : "StudioOptions.held_out", "must be at most 999, got ",
               std::max(views, held_out));
  if (width < 8 || height < 8 || width > 8192 || height > 8192)
    FailOption("StudioOptions.width", "and height must be in 8..8192, got ", width, "x", height);
  if (supersample < 1 || supersample > 16)
    FailOption("StudioOptions.supersample", "must be in 1..16, got ", supersample);
  if (backdrop_supersample < 1 || backdrop_supersample > 16)
    FailOption("StudioOptions.backdrop_supersample", "must be in 1..16, got ", backdrop_supersample);
  if (!(fov_degrees > 1 && fov_degrees < 150))
    FailOption("StudioOptions.fov_degrees", "must be in (1, 150), got ", fov_degrees);
  if (!(margin >= 0 && margin < 0.9)) FailOption("StudioOptions.margin", "must be in [0, 0.9), got ", margin);
  if (!(min_elevation_degrees > -80 && max_elevation_degrees < 89 && min_elevation_degrees <= max_elevation_degrees))
    FailOption("StudioOptions.min_elevation_degrees", "must satisfy -80 < min (", min_elevation_degrees, ") <= max (",
               max_elevation_degrees, ") < 89 degrees");
  if (!(sun_elevation_degrees > 0 && sun_elevation_degrees <= 90))
    FailOption("StudioOptions.sun_elevation_degrees", "must be in (0, 90], got ", sun_elevation_degrees);
  const int extra = CameraModelParamCount(camera_model) -
                    (camera_model == CameraModel::kPinhole || camera_model == CameraModel::kOpenCV ? 4 : 3);
  if (!distortion.empty() && static_cast<int>(distortion.size()) != extra)
    FailOption("StudioOptions.distortion", "for camera model ", CameraModelName(camera_model), " takes ", extra,
               " parameter(s), got ", distortion.size());
  for (double k : distortion)
    if (!std::isfinite(k) || std::abs(k) > 1)
      FailOption("StudioOptions.distortion", "parameter ", k, " is outside [-1, 1]");
  if (supersample * std::max(width, height) > 16384)
    FailOption("StudioOptions.supersample", "x size (", supersample * std::max(width, height),
               ") exceeds 16384 samples");
}

Camera MakeStudioCamera(const StudioOptions& options) {
  const double half_fov = 0.5 * options.fov_degrees * std::numbers::pi / 180;
  const double focal = 0.5 * std::min(options.width, options.height) / std::tan(half_fov);
  const double cx = 0.5 * options.width, cy = 0.5 * options.height;
  Camera camera;
  camera.model = options.camera_model;
  camera.width = options.width;
  camera.height = options.height;
  switch (options.camera_model) {
    case CameraModel::kPinhole:
    case CameraModel::kOpenCV:
      camera.params = {focal, focal, cx, cy};
      break;
    default:
      camera.params = {focal, cx, cy};
  }
  const size_t extra = static_cast<size_t>(CameraModelParamCount(options.camera_model)) - camera.params.size();
  for (size_t i = 0; i < extra; ++i)
    camera.params.push_back(i < options.distortion.size() ? options.distortion[i] : 0.0);
  camera.Check();
  return camera;
}

}  // namespace voltree
