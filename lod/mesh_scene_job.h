// `voltree render SCENE --lod mesh|points|ellipsoids|cook`: the render job (frames, video,
// statistics: render/tree_renderer_job.h) with the scene's meshes drawn by a mesh LOD method.
#pragma once

#include <vector>

#include "core/progress.h"
#include "lod/mesh_lod_options.h"
#include "render/scene.h"
#include "render/tree_renderer_job.h"
#include "samples/tree_source.h"
#include "samples/tree_mesh.h"

namespace voltree {

// The tree a scene's mesh entry names: a preset, or a mesh file (resolved against the scene's
// asset folder).
TreeSource SceneMeshSource(const SceneMeshRef& mesh);

// Grows the presets and imports the files, in Scene::meshes order. Errors name the scene and the
// mesh ("forest.json: meshes.birch: mesh file not found: trees/birch.glb"); import warnings go
// to `notes`.
std::vector<TreeMesh> LoadSceneMeshes(const Scene& scene, Progress& progress, std::vector<std::string>* notes);

RenderJobResult RunMeshSceneRenderJob(const RenderJobOptions& job, const MeshLodOptions& lod, Progress* progress);

}  // namespace voltree
