// Draws a .vtree asset with OpenGL (Reche 2004 / Linz 2006 billboard clouds).
//
// Built once per asset: the DXT5 atlas as one GL_COMPRESSED_RGBA_S3TC_DXT5_EXT texture (linear
// filtering, no mipmaps: tiles are packed edge to edge) and each tile's alpha extent; the octree
// and its billboards stay on the CPU. Each frame: the two input views nearest in angle are chosen
// (SelectViews), a CPU back-to-front traversal picks the cells (TraverseBackToFront, LOD), and one
// 16-byte record per cell (its coordinates and level, the tiles of its billboards for views A and
// B: render/frame_record.h) goes into one buffer drawn by ONE instanced draw call of
// camera-facing quads.
//
// Geometry: a cell's billboard for input view v is the square of side `billboard_scale` x cell
// edge through the cell centre parallel to v's image plane, exactly what reconstruct textured.
// The quad we rasterize faces the current camera and bounds both squares, trimmed to where their
// alpha tiles can be non-zero (render/alpha_extent.h); the fragment shader
// intersects the pixel's ray with each square's plane, so each texture is seen exactly as
// oriented like its input view (from an input camera the image is the photo's billboard
// decomposition, pixel-exactly). RGB comes from the tile `colour`, A from the tile `alpha`,
// lookups clamped half a texel inside the tile so that filtering never bleeds; the two views are
// blended by their angular weights and composited premultiplied over
// (GL_ONE, GL_ONE_MINUS_SRC_ALPHA), depth-tested against opaque geometry without writing depth.
// Colours stay in the atlas's sRGB encoding throughout (as the photos composite).
//
// Instances: Draw takes the instance's similarity (InstanceTransform). The CPU side (view
// selection, traversal, LOD) works in the asset's frame with the eye and view direction mapped
// into it; a similarity scales cell sizes and distances alike, so the LOD rules' texel-per-pixel
// ratio is the same in either frame and scale is honoured. The shaders get the model transform as
// uniforms and do everything else in world space, so depth is the world's and trees depth-test
// correctly against other geometry drawn in the same frame (the scene's ground).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/fragment_counter.h"
#include "render/framebuffer.h"
#include "render/gl_objects.h"
#include "render/instance_transform.h"
#include "render/frame_record.h"
#include "render/lod.h"
#include "render/offscreen_render.h"
#include "render/projection.h"
#include "render/shader.h"
#include "render/traversal.h"
#include "render/view_selection.h"

namespace voltree {

struct TreeRenderOptions {
  LodOptions lod;
  std::array<float, 4> background = {0, 0, 0, 0};  // straight RGBA in [0, 1]; transparent by default
  double billboard_scale = 1.0;                    // billboard side / cell edge, as reconstruct used
  bool lod_history = true;         // LOD hysteresis from the previous frames' choices (frames then depend
                                   // on the sequence rendered before them, deterministically)
  bool tint_levels = false;        // colour each billboard by its octree level (LOD figures)
  bool nearest_view_only = false;  // draw only the nearest input view's billboards (to see what the blend adds)
  bool count_fragments = false;    // FrameStats::fragments, where the driver can count them (FragmentCounter)
  bool trim_quads = true;          // each quad bounds only where its billboards' alpha can be non-zero, and billboards
                           // that are 0 everywhere are skipped (AlphaTileExtents): the same image, fewer fragments
  void Check() const;
};

// How one Draw places the tree in the frame.
struct TreeDraw {
  InstanceTransform model;                    // asset -> world
  std::optional<DepthRange> depth;            // a frame's shared range; default: this instance's sphere
  std::vector<uint8_t>* lod_state = nullptr;  // per-instance LOD history; default: the renderer's own
                                              // (when options.lod_history)
  bool finish = true;  // glFinish, so frame_ms includes the GPU work (a scene finishes once per frame)
};

// Bytes the renderer keeps on the GPU for one asset.
struct GpuMemory {
  size_t buffers = 0;  // alpha extents and the frame's records (FrameRecord: 16 bytes per cell drawn)
  size_t atlas = 0;    // DXT5 texture
  size_t Total() const { return buffers + atlas; }
};

struct FrameStats {
  size_t cells = 0;       // cells drawn
  size_t billboards = 0;  // billboard textures fetched (up to two per cell)
  int min_level = -1, max_level = -1;
  std::vector<size_t> cells_per_level;  // cells drawn at each octree level (index = level)
  ViewPair views;
  int64_t fragments = -1;   // fragment shader invocations (options.count_fragments); -1: not counted
  double traversal_ms = 0;  // CPU traversal and record building
  double frame_ms = 0;      // traversal + upload + draw + glFinish (no read-back)
};

class TreeRenderer {
 public:
  // Needs a current GL context (4.3+). Throws Error when the atlas or buffers cannot be made.
  explicit TreeRenderer(const VtreeAsset& asset);
  TreeRenderer(const TreeRenderer&) = delete;
  TreeRenderer& operator=(const TreeRenderer&) = delete;

  const OctreeIndex& index() const { return index_; }
  // A sphere in the asset's frame that holds every billboard of every level (the root cube's, or
  // wider when billboards are scaled beyond their cells).
  Eigen::Vector3d BoundingCenter() const { return centre_; }
  double BoundingRadius(double billboard_scale) const;
  GpuMemory GpuBytes() const;

  // The cells and records of one frame without drawing (what Draw uploads); `lod_state` as in
  // TraverseBackToFront (Draw passes its own when options.lod_history). `model` places the tree.
  FrameStats Plan(const View& camera, const TreeRenderOptions& options, std::vector<FrameRecord>* records,
                  std::vector<uint8_t>* lod_state = nullptr, const InstanceTransform& model = {}) const;
  void ResetLodHistory() { lod_state_.clear(); }
  // Draws into the bound framebuffer (viewport = the camera's image) with ONE draw call. Depth
  // test on, depth write off; the caller clears. Blend state is restored to disabled afterwards.
  FrameStats Draw(const View& camera, const TreeRenderOptions& options, const TreeDraw& draw = {});
  // Renders into an internal framebuffer of the camera's size; straight-alpha RGBA8.
  Image8 Render(const View& camera, const TreeRenderOptions& options, FrameStats* stats = nullptr);

 private:
  std::vector<VtreeView> views_;
  int texels_;
  OctreeIndex index_;
  Eigen::Vector3d centre_;
  double root_size_;
  size_t atlas_bytes_ = 0;
  ShaderProgram program_;
  std::vector<uint32_t> cell_codes_;     // per cell, its coordinates as FrameRecord packs them
  GlBuffer alpha_extents_;               // per atlas tile, AlphaExtent::Packed
  std::vector<bool> empty_alpha_tiles_;  // per atlas tile: alpha 0 everywhere
  GlStreamBuffer records_;               // the frame's FrameRecords
  GlTexture atlas_;                      // DXT5
  GlVertexArray vertex_array_;
  std::vector<uint8_t> lod_state_;  // per cell: refined in the previous frame
  std::unique_ptr<Framebuffer> target_;
  std::unique_ptr<FragmentCounter> fragment_counter_;  // made on the first counted frame, when available
};

}  // namespace voltree
