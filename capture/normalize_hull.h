// A coarse visual hull of the tree from its mattes: the voxels whose projection falls on the tree
// in every photo that sees them. Used for the scene bounds and the base of the trunk.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct HullOptions {
  int resolution = 96;            // voxels along the longest side of the region
  double matte_threshold = 0.25;  // alpha (0..1) above which a pixel is the tree; low for thin twigs
  // A voxel must be seen (inside the image, in front) by at least this fraction of the views:
  // voxels only a few cameras see are unconstrained.
  double min_seen_fraction = 0.5;
  void Check() const;  // throws Error
};

struct VisualHull {
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero();  // of the kept voxels (their full extent)
  Eigen::Vector3d bounds_max = Eigen::Vector3d::Zero();
  // Centre of the lowest slice of kept voxels, at that slice's bottom face (hull frame: +Z up).
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  size_t voxels = 0;
  double voxel_size = 0;
};

// Carves the box [region_min, region_max] against the mattes (one 1-channel 8-bit matte per view,
// any size: it is scaled to the camera's). Views are in a frame with +Z up. Each matte is dilated
// by a voxel's projected size so that twigs thinner than a voxel still keep it (a conservative
// hull). Throws Error when nothing survives (the mattes and cameras disagree).
VisualHull CarveVisualHull(const std::vector<View>& views, const std::vector<Image8>& mattes,
                           const Eigen::Vector3d& region_min, const Eigen::Vector3d& region_max,
                           const HullOptions& options);

// Carves twice: first a cube around the point the cameras look at (half-size the mean camera
// distance, which holds any tree that fits in views up to 90 degrees wide), then the first hull's
// bounds plus a margin, for finer bounds at the same resolution.
VisualHull CarveVisualHullAuto(const std::vector<View>& views, const std::vector<Image8>& mattes,
                               const HullOptions& options);

}  // namespace voltree
