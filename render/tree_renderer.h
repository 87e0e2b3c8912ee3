// Draws a .vtree asset with OpenGL (Reche 2004 / Linz 2006 billboard clouds).
//
// Built once per asset: the cells of every level (centre, side) and the billboard records
// (colour tile, alpha tile) as shader storage buffers, the DXT5 atlas as one
// GL_COMPRESSED_RGBA_S3TC_DXT5_EXT texture (linear filtering, no mipmaps: tiles are packed edge
// to edge). Each frame: the two input views nearest in angle are chosen (SelectViews), a CPU
// back-to-front traversal picks the cells (TraverseBackToFront, LOD), and one record per cell
// (cell, billboard of view A, billboard of view B) goes into one buffer drawn by ONE instanced
// draw call of camera-facing quads.
//
// Geometry: a cell's billboard for input view v is the square of side `billboard_scale` x cell
// edge through the cell centre parallel to v's image plane, exactly what reconstruct textured.
// The quad we rasterize faces the current camera and bounds both squares; the fragment shader
// intersects the pixel's ray with each square's plane, so each texture is seen exactly as
// oriented like its input view (from an input camera the image is the photo's billboard
// decomposition, pixel-exactly). RGB comes from the tile `colour`, A from the tile `alpha`,
// lookups clamped half a texel inside the tile so that filtering never bleeds; the two views are
// blended by their angular weights and composited premultiplied over
// (GL_ONE, GL_ONE_MINUS_SRC_ALPHA), depth-tested against opaque geometry without writing depth.
// Colours stay in the atlas's sRGB encoding throughout (as the photos composite).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/framebuffer.h"
#include "render/lod.h"
#include "render/shader.h"
#include "render/traversal.h"
#include "render/view_selection.h"

namespace voltree {

struct TreeRenderOptions {
  LodOptions lod;
  std::array<float, 4> background = {0, 0, 0, 0};  // straight RGBA in [0, 1]; transparent by default
  double billboard_scale = 1.0;                    // billboard side / cell edge, as reconstruct used
  bool lod_history = true;  // LOD hysteresis from the previous frames' choices (frames then depend
                            // on the sequence rendered before them, deterministically)
  void Check() const;
};

struct FrameStats {
  size_t cells = 0;       // cells drawn
  size_t billboards = 0;  // billboard textures fetched (up to two per cell)
  int min_level = -1, max_level = -1;
  ViewPair views;
  double traversal_ms = 0;  // CPU traversal and record building
  double frame_ms = 0;      // traversal + upload + draw + glFinish (no read-back)
};

class TreeRenderer {
 public:
  // Needs a current GL context (4.3+). Throws Error when the atlas or buffers cannot be made.
  explicit TreeRenderer(const VtreeAsset& asset);
  ~TreeRenderer();
  TreeRenderer(const TreeRenderer&) = delete;
  TreeRenderer& operator=(const TreeRenderer&) = delete;

  const OctreeIndex& index() const { return index_; }

  // The cells and records of one frame without drawing (what Draw uploads); `lod_state` as in
  // TraverseBackToFront (Draw passes its own when options.lod_history).
  FrameStats Plan(const View& camera, const TreeRenderOptions& options, std::vector<std::array<uint32_t, 4>>* records,
                  std::vector<uint8_t>* lod_state = nullptr) const;
  void ResetLodHistory() { lod_state_.clear(); }
  // Draws into the bound framebuffer (viewport = the camera's image). Depth test on, depth write
  // off; the caller clears. Blend state is restored to disabled afterwards.
  FrameStats Draw(const View& camera, const TreeRenderOptions& options);
  // Renders into an internal framebuffer of the camera's size; straight-alpha RGBA8.
  Image8 Render(const View& camera, const TreeRenderOptions& options, FrameStats* stats = nullptr);

 private:
  std::vector<VtreeView> views_;
  int texels_;
  OctreeIndex index_;
  Eigen::Vector3d centre_;
  double radius_;
  ShaderProgram program_;
  unsigned cells_buffer_ = 0, billboards_buffer_ = 0, frame_buffer_ = 0, atlas_ = 0, vertex_array_ = 0;
  size_t frame_buffer_bytes_ = 0;
  std::vector<uint8_t> lod_state_;  // per cell: refined in the previous frame
  std::unique_ptr<Framebuffer> target_;
};

// Straight alpha from premultiplied RGBA8 (rounded; colour 0 where alpha is 0).
Image8 Unpremultiply(const Image8& premultiplied);

}  // namespace voltree
