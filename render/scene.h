// Scenes: many instances of a few trees on a ground plane, read from JSON. A tree is a .vtree
// asset, a mesh (a preset or a mesh file, drawn by `render --lod METHOD`), or both under one name.
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
// meshes (optional): name -> the tree as a mesh, for the mesh LOD methods: a preset name or a
// .gltf/.glb/.obj path (relative like the assets), or {"tree": ..., "up": "y"|"z", "seed": N}.
// A name in both is one tree, captured (the asset) and modelled (the mesh). At least one of
// assets and meshes names a tree.
// ground (optional): a square (size: number) or rectangle (size: [x, y]) on z = 0 centred at
// `centre` ([x, y], default [0, 0]), opaque sRGB colour 0..255.
// instances: asset (a name in assets or meshes), position [x, y, z] of the asset's origin (the base of the trunk),
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

// A tree as a mesh: which one is the lod layer's to say (render does not know the presets).
struct SceneMeshRef {
  std::string name;
  std::string tree;            // as written: a preset name or a mesh file
  std::filesystem::path path;  // `tree` resolved against the asset folder, for a mesh file
  std::string up = "y";        // mesh files: the up axis, y or z
  uint64_t seed = 1;           // presets: the seed they grow from
};

struct SceneInstance {
  int asset = -1;  // index into Scene::assets; -1: the name is a mesh only
  InstanceTransform transform;
  int mesh = -1;  // index into Scene::meshes; -1: the name is an asset only
};

struct SceneGround {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  // extent along x and y
  std::array<uint8_t, 3> colour = {96, 110, 70};   // sRGB
};

struct Scene {
  std::string name;                   // the file as the user named it; prefixes error messages
  std::vector<SceneAssetRef> assets;  // sorted by name
  std::vector<SceneMeshRef> meshes;   // sorted by name
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
  // What will be drawn: the meshes (every instance needs one; their files are the lod layer's to
  // read) or the assets (every instance needs one, and the files must exist).
  bool meshes = false;
};

// Reads and parses `file`, then checks that every instance has what will be drawn and that every
// asset file exists (naming the missing ones).
Scene LoadScene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

// Reads the scene's assets in Scene::assets order; errors name the scene and the asset.
std::vector<VtreeAsset> ReadSceneAssets(const Scene& scene);

}  // namespace voltree
