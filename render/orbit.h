// Cameras on a circle around a tree, for `voltree render --orbit N`.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"
#include "core/vtree.h"

namespace voltree {

struct OrbitOptions {
  int frames = 36;
  int width = 512, height = 512;
  double margin = 1.1;  // the tree's bounding sphere fills 1/margin of the shorter image side
  void Check() const;
};

// N PINHOLE cameras on a horizontal circle (+Z up) about the centre of the asset's bounds, at
// the input views' mean distance and mean elevation from that centre, looking at it; the first
// frame is at the azimuth of the first input view; frames are named frame_000.png, ...
std::vector<View> OrbitCameras(const VtreeAsset& asset, const OrbitOptions& options);

// N PINHOLE cameras on a horizontal circle about `centre` at `distance` and `elevation_degrees`,
// starting at `azimuth_degrees`, with a field of view that holds a sphere of `radius` about the
// centre (times the margin).
std::vector<View> OrbitCamerasAround(const Eigen::Vector3d& centre, double radius, double distance,
                                     double elevation_degrees, double azimuth_degrees, const OrbitOptions& options);

}  // namespace voltree
