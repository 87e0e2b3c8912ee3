// The LOD bench: the full mesh as the reference, and each leaf-pruning method (and the primitive
// methods: points and lines, clustered ellipsoids) drawn at a sweep of screen sizes from the
// studio's held-out ring and from above, measured for cost (leaves, triangles and primitives
// drawn, GPU bytes, draw time, fragments) and for quality against the full mesh at the same size
// (precision and recall of covered pixels, multi-scale RMS, RGB and alpha PSNR).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/progress.h"
#include "lod/detail_level_selection.h"
#include "lod/ellipsoid_clusters.h"
#include "lod/point_line_hierarchy.h"
#include "lod/pr_optimal_scale.h"
#include "lod/rendering_priority.h"
#include "samples/studio_options.h"
#include "samples/tree_mesh.h"

namespace voltree {

struct LodBenchOptions {
  // The frame: the largest size, where the tree fills the frame as in the studio's photos
  // (StudioOptions.width/height, margin, fov), and the rig (held_out, seed, supersample).
  StudioOptions studio = [] {
    StudioOptions options;
    options.supersample = 2;
    options.backdrop = BackdropStyle::kPlain;
    return options;
  }();
  // Screen sizes: the tree is framed as in the frame, in an image this many pixels tall.
  std::vector<int> sizes = {512, 256, 128, 64, 32};
  double min_lambda = 0.01;  // the smallest fraction of leaves any size keeps
  uint64_t seed = 1;         // the random priority order of the leaves
  int top_views = 2;         // views from 80 degrees above the horizon, besides the held-out ring
  // Neubert's preprocessing: on the studio's input views (up to this many), at each size.
  int preprocess_views = 6;
  // A .vtree asset of the same tree, in the mesh's frame (as the studio and reconstruction make
  // it), drawn by the asset renderer (render/tree_renderer.h, its own LOD) as the row "asset";
  // empty: none.
  std::filesystem::path asset;
  // Keep the first view of every row and of the reference (written as views/METHOD_SIZE.png).
  bool save_views = false;
  // The primitive methods: Deussen et al.'s points and lines, Clasen et al.'s ellipsoids.
  PointLineOptions points;
  EllipsoidClusterOptions ellipsoids;
  // Neubert's rendering priority (the rows neubert-priority and neubert-matched); its jitter's
  // seed is `seed`.
  RenderingPriorityOptions priority;

  // Throws OptionError naming the field (sizes outside [8, frame height], min_lambda outside (0, 1]).
  void Check() const;
};

// One method at one size, the views pooled (coverage counts summed, squared errors averaged).
struct LodBenchRow {
  std::string method;
  int size = 0;
  double lambda = 1;          // fraction of leaves drawn
  double area_scale = 1;      // of each drawn leaf (vmi: their mean)
  size_t leaves = 0;          // drawn as polygons
  size_t triangles = 0;       // points and ellipsoids: lines are 2 each, ellipsoids their sphere's
  size_t primitives = 0;      // points, lines and ellipsoids drawn
  int level = -1;             // ellipsoids: the clustering drawn (its number of clusters asked of EM)
  size_t geometry_bytes = 0;  // vertex and index buffers
  size_t texture_bytes = 0;
  double draw_ms = 0;      // median over the views
  int64_t fragments = -1;  // mean over the views; -1 not available
  double precision = 1, recall = 1, pr_score = 1;
  double multiscale_rms = 0;
  double rgb_psnr = 0, alpha_psnr = 0;  // +infinity when identical to the reference
};

// Neubert's preprocessing for one size and its lambda: every candidate scale's PR, and the
// chosen one.
struct ScaleSearch {
  std::string method = "neubert";  // neubert: the random order; neubert-priority: the priority order
  int size = 0;
  double lambda = 1;
  std::vector<ScaleTrial> trials;
  ScaleTrial best;
};

// Neubert's detail level selection at one size: Cook's lambda and quality there (random order,
// s = 1 / lambda), the geometry levels tried with the priority order and PR-optimal scale, and
// the quality-matched level.
struct LevelSelection {
  int size = 0;
  double cook_lambda = 1;
  double target = 1;  // Q(lambda_Cook, s_Cook) on the input views
  std::vector<LevelSample> samples;
  LevelSample matched;
};

// Clasen's calibration of the ellipsoids' size at one size: every candidate scale of the
// semi-axes with its multi-scale RMS on the training views, and the chosen one.
struct EllipsoidCalibration {
  int size = 0;
  int clusters = 0;
  std::vector<std::pair<double, double>> trials;  // scale, multi-scale RMS
  double scale = 1, ms_rms = 0;
};

struct SavedView {
  std::string name;  // METHOD_SIZE, or reference_SIZE
  Image8 image;      // RGBA, straight alpha
};

struct LodBenchResult {
  std::string tree;
  std::string renderer;  // the GL renderer's name
  size_t leaf_count = 0, triangle_count = 0;
  double leaf_area = 0;
  int views = 0;  // per size
  bool fragments_available = false;
  std::vector<std::string> methods;
  std::vector<std::string> notes;  // e.g. which methods a mesh without leaves could not run
  std::vector<LodBenchRow> rows;
  std::vector<ScaleSearch> scale_searches;
  double preprocess_seconds = 0;  // Neubert's scale search, all sizes
  double priority_seconds = 0;    // Neubert's rendering priority order
  std::vector<LevelSelection> level_selections;
  double level_selection_seconds = 0;  // Neubert's detail level selection, all sizes
  double vmi_seconds = 0;              // the VMI removal sequence
  double skeleton_seconds = 0;         // the branch skeleton from the bark (both primitive methods)
  double points_seconds = 0;           // sampling the points
  size_t sampled_points = 0, skeleton_segments = 0;
  double ellipsoid_seconds = 0;       // the EM fits of every level and their ellipsoids
  double line_merge_seconds = 0;      // the branch lines merged down to one
  std::vector<int> ellipsoid_levels;  // clusters asked at each level, and ellipsoids kept
  std::vector<size_t> ellipsoid_counts;
  std::vector<EllipsoidCalibration> ellipsoid_calibrations;
  double ellipsoid_calibration_seconds = 0;
  std::vector<SavedView> saved_views;  // with save_views
};

// The methods: "full" (the reference mesh itself), "pruned" (lambda, no scaling), "cook"
// (lambda, s = 1 / lambda), "neubert" (lambda, PR-optimal s), "neubert-priority" (the same with
// the rendering priority order instead of the random one), "neubert-matched" (the priority order
// at the quality-matched lambda and its PR-optimal s) and "vmi" (lambda, leaves removed
// in the VMI order, each removal growing its nearest leaf; area_scale is the mean). Needs a GL
// context of its own. With options.asset, also "asset": triangles are 2 per cell drawn, GPU bytes
// its buffers and DXT5 atlas, draw time the renderer's frame time, fragments not measured.
// "points" (Deussen et al. 2002: a prefix of points and lines, or the mesh where more points are
// needed than sampled) and "ellipsoids" (Clasen et al.: a level of leaf-cluster ellipsoids and of
// simplified branch lines) run on whichever of leaves and bark the mesh has.
LodBenchResult RunLodBench(const TreeMesh& mesh, const std::string& tree_name, const LodBenchOptions& options,
                           Progress& progress);

}  // namespace voltree
