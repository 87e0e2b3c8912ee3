// The reconstruct stage on a capture workspace DIR: reads sparse/ (COLMAP text), mattes/,
// foreground/ (or images/ as a fallback colour source) and scene.json, and writes DIR/volume/.
#pragma once

#include <filesystem>
#include <optional>

#include "core/progress.h"
#include "reconstruct/reconstruct.h"

namespace voltree {

struct SceneBounds {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
};

// Bounds from DIR/scene.json, or nothing when the file is absent. Errors name the file and field.
std::optional<SceneBounds> ReadSceneBounds(const std::filesystem::path& scene_json);

// Bounds of a coarse visual hull (32^3 cells) carved inside `initial`, for workspaces without
// scene.json; throws Error when nothing survives.
SceneBounds VisualHullBounds(const std::vector<View>& views, const std::vector<Image8>& mattes,
                             const SceneBounds& initial, double carve_alpha);

// Matte path of an image name: images/a/view_000.jpg -> mattes/a/view_000.png.
std::filesystem::path CompanionPath(const std::filesystem::path& dir, const char* folder, const std::string& name);

ReconstructInput LoadReconstructInput(const std::filesystem::path& dir, const ReconstructOptions& options,
                                      Progress* progress);

struct ReconstructWorkspaceOptions {
  ReconstructOptions reconstruct;
  bool force = false;  // replace an existing DIR/volume
};

// Loads, reconstructs and writes DIR/volume atomically. Refuses an existing volume/ without force
// before any work is done.
Volume ReconstructWorkspace(const std::filesystem::path& dir, const ReconstructWorkspaceOptions& options,
                            Progress& progress);

}  // namespace voltree
