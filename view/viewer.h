// `voltree view`: an asset or a scene in a desktop window (GLFW), drawn by the native renderer
// (render/tree_renderer.h, render/scene_renderer.h) into the window's framebuffer, with a Dear
// ImGui panel of statistics and toggles.
//
// Mouse: left drag turns the orbit, right drag pans, the wheel zooms. Keys: W A S D fly (on the
// ground's plane), R reset, T level tint, L LOD rule (screen / planes), 0-9 force that octree level
// (the same key again: automatic LOD), V the nearest input view alone or the two-view blend, U
// pruning off and on, P save a screenshot, Escape quit. A pruned billboard is not in the asset, so
// pruning off draws a second asset of the same capture built without it (--unpruned FILE:
// reconstruct --prune 1, then compress). A screenshot is the window's pixels (without the panel)
// as PNG plus its camera as a COLMAP text model, so that
// `voltree render ASSET --cameras DIR/view_000 --background 128,128,128` draws the same view.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

struct ViewerOptions {
  std::filesystem::path input;         // a .vtree asset or a scene .json
  std::filesystem::path asset_folder;  // scenes: where their assets are (default: the scene's folder)
  int width = 1024, height = 768;      // window size
  std::array<float, 4> background = {128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1};  // opaque, eval's grey
  std::filesystem::path unpruned;      // optional: the asset's capture built without pruning, drawn after U
  std::filesystem::path script;        // optional: scripted events (view/viewer_script.h); ends the session
  std::filesystem::path output = ".";  // where screenshots go: view_NNN.png and view_NNN/ (COLMAP model)
  bool panel = true;                   // the ImGui panel
  void Check() const;
};

struct ViewerResult {
  std::vector<std::filesystem::path> screenshots;
  int frames = 0;
  double median_ms = 0;  // of the frames' draw times (traversal, upload, draw, glFinish; no panel, no swap)
  std::string renderer;  // GL_RENDERER
};

// Throws Error with a clear message when there is no display or no OpenGL 4.3 core context.
ViewerResult RunViewer(const ViewerOptions& options);

}  // namespace voltree
