// What the photo studio photographs and how: camera rings, image size, supersampling, lens, sun.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/camera.h"

namespace voltree {

// What stands behind the tree. kRealistic: a place (a skyline of hills, tree lines and buildings,
// bushes, rocks and other trees on textured ground), what COLMAP and the matting face in real
// photos. kPlain: sky and textured ground only (the studio before the realistic backdrop).
enum class BackdropStyle { kRealistic, kPlain };
BackdropStyle BackdropStyleFromName(const std::string& name);  // "realistic", "plain"; Error otherwise
const char* BackdropStyleName(BackdropStyle style);

struct StudioOptions {
  std::string tree_name = "mesh";  // recorded in truth/meta.json
  int views = 24;                  // input photos, spread over the rings
  int rings = 2;                   // camera rings at different elevations
  int held_out = 8;                // truth views between the rings, at other azimuths
  int width = 512;
  int height = 512;
  int supersample = 4;  // samples per pixel and axis, box-filtered (mattes get 1/s^2 steps)
  // The same for the sky and ground, at most `supersample`: they need anti-aliasing, not
  // fractional coverage, and are the costliest shader (2x2 is a quarter of the 4x4 time).
  int backdrop_supersample = 2;
  uint64_t seed = 1;  // ground and sky texture, clutter, first azimuth of the rings
  BackdropStyle backdrop = BackdropStyle::kRealistic;
  CameraModel camera_model = CameraModel::kPinhole;
  // The model's parameters after focal length and principal point (SIMPLE_RADIAL: k;
  // RADIAL: k1 k2; OPENCV: k1 k2 p1 p2); empty means no distortion.
  std::vector<double> distortion;
  double fov_degrees = 40;            // across the smaller image side
  double margin = 0.08;               // fraction of the half-frame kept free around the tree's bounds
  double min_elevation_degrees = 5;   // lowest ring, above the horizon
  double max_elevation_degrees = 35;  // highest ring
  double sun_azimuth_degrees = 135;
  double sun_elevation_degrees = 50;

  // Throws Error naming the offending field.
  void Check() const;
};

// The studio's intrinsics: principal point at the image centre, focal length from the field of
// view, the lens distortion of `options`.
Camera MakeStudioCamera(const StudioOptions& options);

}  // namespace voltree
