// COLMAP sparse models (cameras, images, points) and their text format
// (https://colmap.github.io/format.html). Binary models are read in capture/.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "core/camera.h"

namespace voltree {

struct ColmapImage {
  int image_id = 0;
  int camera_id = 0;
  std::string name;
  Pose pose;
  std::vector<Eigen::Vector2d> keypoints;  // POINTS2D: x, y
  std::vector<int64_t> point3d_ids;        // parallel to keypoints, -1 for none
};

struct ColmapPoint {
  int64_t point_id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::array<uint8_t, 3> color = {0, 0, 0};
  double error = 0;
  std::vector<std::pair<int, int>> track;  // (image_id, point2d index)
};

struct ColmapModel {
  std::map<int, Camera> cameras;
  std::map<int, ColmapImage> images;
  std::map<int64_t, ColmapPoint> points;

  // The registered images as Views, sorted by image name.
  std::vector<View> Views() const;
  // Throws Error when an image names a camera that is not in the model.
  void Check() const;
};

// Observations over all points (the sum of their track lengths).
size_t ObservationCount(const ColmapModel& model);
// Mean distance in pixels between each observation and its 3D point's projection; 0 without
// observations (a model stripped of its POINTS2D).
double MeanReprojectionError(const ColmapModel& model);

// Reads cameras.txt, images.txt and points3D.txt (points optional) from `folder`; also accepts the
// rig-aware layout of newer COLMAP (rigs.txt, frames.txt beside them). Errors name file and line.
ColmapModel ReadColmapText(const std::filesystem::path& folder);
// Writes the three files atomically, with COLMAP's header comments; full double precision.
void WriteColmapText(const std::filesystem::path& folder, const ColmapModel& model);

}  // namespace voltree
