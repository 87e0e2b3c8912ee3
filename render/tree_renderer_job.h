// `voltree render`: frames of a .vtree asset or of a scene (.json, render/scene.h) from an orbit
// or from a COLMAP camera model, written as straight-alpha RGBA PNGs into a staged output folder
// and/or as a turntable video (ffmpeg), with timing statistics.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/progress.h"
#include "render/frame_source.h"
#include "render/tree_renderer.h"

namespace voltree {

struct RenderJobOptions {
  std::filesystem::path asset;         // a .vtree, or a scene .json
  std::string asset_label;             // how frames.json names the asset (default: its path)
  std::filesystem::path asset_folder;  // scenes: where their assets are looked up (default: the scene's folder)
  int orbit = 0;                       // > 0: that many orbit frames
  std::filesystem::path cameras;       // else: a COLMAP text model; frames named after its images
  int width = 0, height = 0;           // 0: from the cameras (orbit: 512x512)
  TreeRenderOptions render;
  int max_level = -1;  // finest octree level loaded from a .vtree (-1: all; beyond the asset: all, with a note)
  std::filesystem::path output;     // frames folder; optional when `turntable` is given
  std::filesystem::path turntable;  // .mp4 of the orbit frames (30 fps, over the background or grey)
  bool force = false;
  void Check() const;
};

struct RenderJobResult {
  std::vector<std::string> frames;           // file names inside the output folder
  std::vector<FrameStats> stats;             // per frame (a scene's: summed over its instances)
  std::vector<MeshFrameCounts> mesh_counts;  // per frame, scenes of meshes only
  double mean_instances_drawn = 1, mean_instances_culled = 0;
  GpuMemory gpu;         // buffers and atlases of all assets
  double median_ms = 0;  // of FrameStats::frame_ms
  double mean_billboards = 0;
  double mean_fragments = -1;  // fragment shader invocations per frame (render.count_fragments); -1: not available
  std::string renderer;        // GL_RENDERER
  // What the frames lack and why: a truncated asset's missing levels, a --max-level cap or clamp.
  std::vector<std::string> notes;
};

// A camera's intrinsics scaled to a new image size (focal lengths and principal point).
Camera ResizeCamera(const Camera& camera, int width, int height);

// `mesh_scene`: draw the scene's meshes with this source (lod/mesh_scene_job.h) instead of its
// assets; only for scenes.
RenderJobResult RunRenderJob(const RenderJobOptions& options, Progress* progress,
                             const MeshSceneSourceFactory& mesh_scene = {});

}  // namespace voltree
