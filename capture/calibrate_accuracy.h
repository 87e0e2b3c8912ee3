// How close estimated cameras are to the true ones, up to the similarity (gauge) that
// structure-from-motion cannot recover.
#pragma once

#include <string>
#include <vector>

#include "capture/normalize.h"
#include "core/camera.h"

namespace voltree {

struct CameraAccuracy {
  int matched = 0;                   // views present in both, by name
  std::vector<std::string> missing;  // true views without an estimate
  Similarity estimated_to_true;      // Umeyama fit of the camera centres
  double mean_rotation_degrees = 0;  // angle of R_true * (R_est * R_align^T)^T per view
  double max_rotation_degrees = 0;
  // |aligned centre - true centre| / mean camera distance, where the distance is from each true
  // camera centre to the centroid of all of them (the tree, for an orbit).
  double mean_center_error = 0;
  double max_center_error = 0;
  struct PerView {
    std::string name;
    double rotation_degrees = 0, center_error = 0;
  };
  std::vector<PerView> views;  // the matched views, in the truth's order
};

// Matches views by name, aligns estimated to true centres (Umeyama with scale; needs 3 matched
// views that are not collinear) and measures the residual rotation and centre errors.
CameraAccuracy CompareCameras(const std::vector<View>& estimated, const std::vector<View>& truth);

}  // namespace voltree
