// What an evaluation compares against: cameras and RGBA truth images of a capture workspace.
//   held-out views: WORKSPACE/truth/sparse (COLMAP text) + truth/rgba/NAME.png (premultiplied
//                   RGBA, as the photo studio writes them); absent when the workspace has no truth/.
//   input views:    WORKSPACE/sparse + foreground/NAME.png (premultiplied RGBA), or else the photo
//                   images/NAME with mattes/NAME.png as its alpha (straight; the photo's colours at
//                   fractional alpha still hold some background, as in reconstruct's fallback).
// When the workspace was calibrated by COLMAP, its frame is not the truth's: the true cameras of
// the input photos, kept in WORKSPACE/truth/input_sparse, give the similarity that moves the
// held-out cameras into the workspace's frame (Umeyama on the camera centres).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "capture/normalize.h"
#include "core/camera.h"
#include "core/image.h"

namespace voltree {

struct TruthView {
  View camera;                   // where to render (name: the view's image name)
  std::filesystem::path colour;  // RGBA truth, or the photo when `matte` is set
  std::filesystem::path matte;   // empty, or the alpha of a photo
  bool premultiplied = false;    // of the image LoadTruthImage returns
  std::filesystem::path parts;   // empty, or truth/parts/NAME.png: coverage of bark (R) and leaves (G)
  // The files' size when the camera was shrunk (SeenFromFarther); 0: the camera's own size.
  int photo_width = 0, photo_height = 0;
};

// Straight or premultiplied RGBA (see TruthView::premultiplied) of the camera's size, area-
// resampled from the photo's when the view is seen from farther; Error names the file when it is
// missing or has another size.
Image8 LoadTruthImage(const TruthView& view);

// The views as cameras `distance` times farther away see them: each camera's image shrunk to
// 1/distance of its size (focal length and principal point with it, so the tree covers the pixels
// it would from there and the LOD picks what it would draw), the truth area-resampled to match.
// Perspective is the camera's own: only the pixel footprint changes.
std::vector<TruthView> SeenFromFarther(std::vector<TruthView> views, double distance);

// The studio's held-out views (with their parts masks when truth/parts/ has them); nothing when
// WORKSPACE/truth/ does not exist. Errors name the
// missing file when truth/ exists but is incomplete.
std::optional<std::vector<TruthView>> HeldOutTruth(const std::filesystem::path& workspace);

// Every registered image of WORKSPACE/sparse with its truth (foreground/, else images/ + mattes/).
std::vector<TruthView> InputTruth(const std::filesystem::path& workspace);

struct TruthAlignment {
  Similarity truth_to_workspace;
  int matched_views = 0;
  double mean_rotation_degrees = 0;  // residual camera rotation after the alignment
  double mean_center_error = 0;      // residual centre error / mean camera distance
};

// The alignment from WORKSPACE/truth/input_sparse to WORKSPACE/sparse, or nothing when
// truth/input_sparse does not exist (the workspace uses the true cameras).
std::optional<TruthAlignment> AlignTruthToWorkspace(const std::filesystem::path& workspace);

// Moves each camera by the similarity (poses only; intrinsics stay the true ones).
void ApplyAlignment(const TruthAlignment& alignment, std::vector<TruthView>* views);

}  // namespace voltree
