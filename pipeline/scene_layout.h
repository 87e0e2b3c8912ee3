// One render scene (render/scene.h's JSON) holding many captured assets: on a square grid, or at
// the positions a survey gives in a CSV. `voltree scene` and the batch workflow's scene rule
// write it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

// Where one tree stands: position on the ground (z = 0), rotation about +Z in degrees, scale.
struct ScenePlacement {
  std::string tree;
  double x = 0, y = 0;
  double rotation = 0;
  double scale = 1;
};

struct SceneLayoutOptions {
  std::vector<std::filesystem::path> assets;  // each named by AssetNameFromPath
  std::filesystem::path positions;            // optional CSV: tree, x, y[, rotation][, scale]
  double spacing = 0;                         // grid spacing in asset units; 0: from the assets' footprints
  std::filesystem::path output;               // the scene .json; asset paths are written relative to its folder
  bool force = false;                         // replace an existing output
  void Check() const;
};

// A capture's asset is named after its folder ("oak_1/tree.vtree" -> "oak_1"); any other file
// after its stem ("assets/pine.vtree" -> "pine").
std::string AssetNameFromPath(const std::filesystem::path& asset);

// Reads a survey CSV: a header naming the columns tree, x, y and optionally rotation and scale
// (any order, any case), then one row per tree; blank lines and lines starting with '#' are
// skipped. Errors name the file, the line and the column.
std::vector<ScenePlacement> ReadPositionsCsv(const std::filesystem::path& csv);

// The trees in the given order, row by row on a square grid centred on the origin.
std::vector<ScenePlacement> GridPlacements(const std::vector<std::string>& trees, double spacing);

// Writes the scene (atomically) and returns the number of instances. Refuses an existing output
// without `force`, a tree without a row in the CSV, or two assets with the same name.
int WriteSceneLayout(const SceneLayoutOptions& options);

}  // namespace voltree
