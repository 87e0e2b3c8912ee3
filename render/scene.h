// Scenes: many instances of a few .vtree assets on a ground plane, read from JSON.
//
//   {
//     "assets": {"oak": "oak.vtree", "pine": "trees/pine.vtree"},
//     "ground": {"size": [120, 120], "colour": [96, 110, 70]},
//     "instances": [
//       {"asset": "oak", "position": [3.5, -2, 0], "rotation": 40, "scale": 1.1},
//       {"asset": "pine", "position": [-8, 4, 0]}
//     ]
//   }
//
// assets: name -> .vtree path, relative to the scene file's folder (or to an override folder).
// ground (optional): a square (size: number) or rectangle (size: [x, y]) on z = 0 centred at
// `centre` ([x, y], default [0, 0]), opaque sRGB colour 0..255.
// instances: asset name, position [x, y, z] of the asset's origin (the base of the trunk),
// rotation about +Z in degrees (default 0), uniform scale > 0 (default 1).
// Every field is checked; unknown keys are errors; messages name the file and the field.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vtree.h"
#include "render/instance_transform.h"

namespace voltree {

struct SceneAssetRef {
  std::string name;
  std::filesystem::path path;  // resolved against the asset folder
};

struct SceneInstance {
  int asset = 0;  // index into Scene::assets
  InstanceTransform transform;
};

struct SceneGround {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  // extent along x and y
  std::array<uint8_t, 3> colour = {96, 110, 70};   // sRGB
};

struct Scene {
  std::string name;                   // the file as the user named it; prefixes error messages
  std::vector<SceneAssetRef> assets;  // sorted by name
  std::vector<SceneInstance> instances;
  std::optional<SceneGround> ground;
};

// Whether `path` names a scene (.json) rather than an asset.
bool IsSceneFile(const std::filesystem::path& path);

// Parses and validates scene JSON; relative asset paths are resolved against `asset_folder`.
// Does not touch the file system. Throws Error "NAME: FIELD ..." on any problem.
Scene ParseScene(std::string_view json, const std::string& name, const std::filesystem::path& asset_folder);

struct SceneLoadOptions {
  std::filesystem::path asset_folder;  // empty: the scene file's folder
};

// Reads and parses `file`, then checks that every asset file exists (naming the missing ones).
Scene LoadScene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

// Reads the scene's assets in Scene::assets order; errors name the scene and the asset.
std::vector<VtreeAsset> ReadSceneAssets(const Scene& scene);

}  // namespace voltree
