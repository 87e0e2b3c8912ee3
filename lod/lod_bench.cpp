#include "lod/lod_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "core/image_metrics.h"
#include "core/vtree.h"
#include "render/tree_renderer.h"
#include "lod/branch_skeleton.h"
#include "lod/colour_correction.h"
#include "lod/leaf_separation.h"
#include "lod/line_simplification.h"
#include "lod/lod_view_renderer.h"
#include "lod/primitive_renderer.h"
#include "lod/surface_colour.h"
#include "lod/pruned_mesh.h"
#include "lod/rendering_priority.h"
#include "lod/screen_size_rule.h"
#include "lod/stochastic_pruning.h"
#include "lod/vmi_pruning.h"
#include "lod/leaf_id_renderer.h"
#include "samples/studio_rig.h"
#include "samples/studio_tree_renderer.h"

namespace voltree {
namespace {

constexpr double kTopElevationDegrees = 80;
constexpr int kVmiSize = 256;                        // the id renders' size, as the VMI paper's
constexpr size_t kVertexBytes = 11 * sizeof(float);  // position, normal, uv, tint as the studio uploads them
constexpr float kClasenLinePixels = 1;               // Clasen et al.'s default line width (sec. 6)
// The candidate scales of the ellipsoids' semi-axes for the calibration by image error: steps of
// 1.2 around 1 (a solid ellipsoid with the cluster's second moments, grown by half a leaf).
constexpr double kEllipsoidScales[] = {0.16, 0.19, 0.23, 0.28, 0.33, 0.4, 0.48, 0.58, 0.69, 0.83, 1.0, 1.2, 1.44};

// The views: the held-out ring, plus `top_views` from high above at azimuths spread evenly, far
// enough that the bounding sphere fits the frame.
std::vector<View> BenchViews(const StudioRig& rig, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             const StudioOptions& studio, int top_views) {
  std::vector<View> views = rig.held_out;
  const double radius = std::max(0.5 * (hi - lo).norm(), 1e-3);
  const double half_angle =
      std::atan(std::tan(0.5 * studio.fov_degrees * std::numbers::pi / 180) * (1 - studio.margin));
  const double distance = std::max(rig.distance, radius / std::sin(half_angle));
  const double elevation = kTopElevationDegrees * std::numbers::pi / 180;
  for (int k = 0; k < top_views; ++k) {
    const double azimuth = 2 * std::numbers::pi * (k + 0.125) / top_views;
    const Eigen::Vector3d direction(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                    std::sin(elevation));
    View view;
    view.name = "top_" + std::to_string(k);
    view.camera = rig.held_out.empty() ? MakeStudioCamera(studio) : rig.held_out.front().camera;
    view.pose = Pose::LookAt(rig.target + distance * direction, rig.target, Eigen::Vector3d::UnitZ());
    views.push_back(view);
  }
  return views;
}

// The same views in an image `size` pixels tall (the tree framed the same way, smaller).
std::vector<View> AtSize(std::vector<View> views, int size) {
  for (View& view : views) {
    const double factor = static_cast<double>(size) / view.camera.height;
    view.camera = view.camera.Resized(std::max(1, static_cast<int>(std::lround(view.camera.width * factor))), size);
  }
  return views;
}

size_t TextureBytes(const TreeMesh& mesh) {
  size_t bytes = 0;
  for (const Image8& texture : mesh.textures) bytes += texture.pixels.size() * 4 / std::max(texture.channels, 1);
  return bytes;
}

size_t GeometryBytes(const TreeMesh& mesh) {
  return mesh.vertices.size() * kVertexBytes + mesh.TriangleCount() * 3 * sizeof(uint32_t);
}

// Metrics of renders against references, views pooled.
struct Pooled {
  CoverageCounts coverage;
  double rgb_mse = 0, alpha_mse = 0, multiscale_rms = 0;
  std::vector<double> draw_ms;
  int64_t fragments = 0;
  int views = 0;
};

double MseFromPsnr(double psnr) { return std::isinf(psnr) ? 0.0 : 255.0 * 255.0 / std::pow(10.0, psnr / 10); }

// `straight`: the render has straight alpha (the asset renderer's); references are premultiplied.
void AddView(Pooled& pooled, const LodFrame& frame, const Image8& reference, bool straight = false) {
  ImageMetricsOptions options;
  options.render_premultiplied = !straight;
  options.truth_premultiplied = true;
  const ViewMetrics metrics = CompareViews(frame.foreground, reference, options);
  pooled.coverage.true_positives += metrics.coverage.true_positives;
  pooled.coverage.false_positives += metrics.coverage.false_positives;
  pooled.coverage.false_negatives += metrics.coverage.false_negatives;
  pooled.rgb_mse += MseFromPsnr(metrics.rgb_psnr);
  pooled.alpha_mse += MseFromPsnr(metrics.alpha_psnr);
  pooled.multiscale_rms += metrics.multiscale_rms;
  pooled.draw_ms.push_back(frame.draw_ms);
  pooled.fragments = frame.fragments < 0 || pooled.fragments < 0 ? -1 : pooled.fragments + frame.fragments;
  ++pooled.views;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The row's quality, draw time and fragments from the pooled views.
void FillQuality(LodBenchRow& row, const Pooled& pooled) {
  row.precision = pooled.coverage.Precision();
  row.recall = pooled.coverage.Recall();
  row.pr_score = PrScore(row.precision, row.recall);
  row.multiscale_rms = pooled.multiscale_rms / pooled.views;
  row.rgb_psnr = PsnrFromMse(pooled.rgb_mse / pooled.views, 255);
  row.alpha_psnr = PsnrFromMse(pooled.alpha_mse / pooled.views, 255);
  row.draw_ms = Median(pooled.draw_ms);
  row.fragments = pooled.fragments < 0 ? -1 : pooled.fragments / pooled.views;
}

// The box that holds the mesh with its leaves scaled by up to `max_area_scale` about their centres.
std::pair<Eigen::Vector3d, Eigen::Vector3d> GrownBounds(const TreeMesh& mesh, double max_area_scale) {
  const auto [lo, hi] = mesh.Bounds();
  const Eigen::Vector3d pad =
      Eigen::Vector3d::Constant(0.5 * std::sqrt(max_area_scale) * (hi - lo).cast<double>().norm() * 0.1);
  return {lo.cast<double>() - pad, hi.cast<double>() + pad};
}

std::vector<Ellipsoid> ScaledEllipsoids(std::vector<Ellipsoid> ellipsoids, double scale) {
  for (Ellipsoid& ellipsoid : ellipsoids) ellipsoid.axes *= static_cast<float>(scale);
  return ellipsoids;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void LodBenchOptions::Check() const {
  studio.Check();
  if (sizes.empty()) FailOption("LodBenchOptions.sizes", "is empty: give at least one screen size");
  const int frame = std::min(studio.width, studio.height);
  for (int size : sizes)
    if (size < 8 || size > frame)
      FailOption("LodBenchOptions.sizes", "has ", size, " px, outside the frame: sizes go from 8 to the frame's ",
                 frame, " px");
  if (!(min_lambda > 0 && min_lambda <= 1))
    FailOption("LodBenchOptions.min_lambda", "is ", min_lambda, ", outside (0, 1]: it is a fraction of the leaves");
  if (top_views < 0 || top_views > 16) FailOption("LodBenchOptions.top_views", "is ", top_views, ", not in 0..16");
  if (!asset.empty() && !std::filesystem::is_regular_file(asset))
    FailOption("LodBenchOptions.asset", "is ", asset.string(), ", which is not a file");
  if (preprocess_views < 1) FailOption("LodBenchOptions.preprocess_views", "is ", preprocess_views, ", not >= 1");
  points.Check();
  ellipsoids.Check();
  priority.Check();
}

namespace {

// One bench run: the mesh, its leaves and priority order, the GL renderer and the cameras.
class LodBench {
 public:
  LodBench(const TreeMesh& mesh, const LodBenchOptions& options)
      : options_(options),
        mesh_(mesh),
        leaves_(SeparateLeaves(mesh)),
        order_(RandomLeafOrder(leaves_.size(), options.seed)),
        frame_(std::min(options.studio.width, options.studio.height)),
        supersample_(options.studio.supersample),
        // Scaled leaves reach past the mesh's bounds: the largest candidate scale is lambda^-1.3.
        draw_bounds_(GrownBounds(mesh, std::pow(options.min_lambda, -1.3))),
        renderer_(options.studio, draw_bounds_.first, draw_bounds_.second),
        rig_(MakeStudioRig(mesh.Bounds().first.cast<double>(), mesh.Bounds().second.cast<double>(), options.studio)),
        views_(BenchViews(rig_, mesh.Bounds().first.cast<double>(), mesh.Bounds().second.cast<double>(), options.studio,
                          options.top_views)),
        full_(mesh),
        crown_(mesh.CrownBounds()) {
    for (int size : options.sizes) lambdas_.push_back(LambdaForScreenSize(size, frame_, options.min_lambda));
  }

  LodBenchResult Run(const std::string& tree_name, Progress& progress) {
    LodBenchResult result;
    result.tree = tree_name;
    result.triangle_count = mesh_.TriangleCount();
    result.leaf_count = leaves_.size();
    result.leaf_area = TotalLeafArea(leaves_);
    result.renderer = renderer_.context().renderer();
    result.fragments_available = renderer_.counts_fragments();
    result.views = static_cast<int>(views_.size());
    result.methods = {"full"};
    if (leaves_.empty()) {
      result.notes.push_back(
          "the mesh has no separable leaves (no alpha-tested or blended material): pruned, cook, neubert, "
          "neubert-priority, neubert-matched, neubert-colour and vmi need leaves");
    } else {
      result.methods.insert(result.methods.end(), {"pruned", "cook", "neubert", "neubert-priority", "neubert-matched",
                                                   "neubert-colour", "vmi"});
      OrderByPriority(result, progress);
      SearchOptimalScales(result, progress);
      SelectDetailLevels(result, progress);
      RankByVmi(result, progress);
    }
    BuildPrimitives(result, progress);
    if (!options_.asset.empty()) {
      asset_ = std::make_unique<TreeRenderer>(ReadAsset(options_.asset));
      result.methods.push_back("asset");
    }
    for (size_t s = 0; s < options_.sizes.size(); ++s) {
      const int size = options_.sizes[s];
      progress.Say("lod-bench", Str(size, " px: lambda ", lambdas_[s]));
      const std::vector<View> at = AtSize(views_, size);
      const std::vector<LodFrame> references = RenderAll(full_, at, ReferenceSupersample(size));
      LodBenchRow reference;
      reference.method = "reference";
      reference.size = size;
      Keep(reference, references.front().foreground, /*straight=*/false);
      for (const std::string& method : result.methods)
        result.rows.push_back(method == "asset"        ? MeasureAsset(size, at, references)
                              : method == "points"     ? MeasurePoints(size, at, references)
                              : method == "ellipsoids" ? MeasureEllipsoids(size, at, references, result)
                                                       : MeasureMethod(method, size, lambdas_[s], at, references));
    }
    result.saved_views = std::move(saved_views_);
    return result;
  }

 private:
  // With save_views, the row's first view, in straight alpha (as PNG stores it).
  void Keep(const LodBenchRow& row, const Image8& image, bool straight) {
    if (!options_.save_views) return;
    Image8 kept = image;
    if (!straight)
      for (size_t p = 0; p + 3 < kept.pixels.size(); p += 4)
        if (const int alpha = kept.pixels[p + 3]; alpha > 0)
          for (size_t c = 0; c < 3; ++c)
            kept.pixels[p + c] = static_cast<uint8_t>(std::min(255, (kept.pixels[p + c] * 255 + alpha / 2) / alpha));
    saved_views_.push_back({Str(row.method, "_", row.size), std::move(kept)});
  }

  // Methods are drawn as a renderer would draw them at that size (the bench's supersampling);
  // the reference is the full mesh sampled as finely as in the frame, so that sub-pixel leaves
  // count with the coverage they have instead of vanishing into the alpha-tested texture's
  // coarse mip levels.
  int ReferenceSupersample(int size) const {
    return std::max(supersample_, static_cast<int>(std::lround(static_cast<double>(frame_) * supersample_ / size)));
  }

  std::vector<LodFrame> RenderAll(const StudioTreeRenderer& tree, const std::vector<View>& at, int samples) {
    std::vector<LodFrame> frames;
    for (const View& view : at) frames.push_back(renderer_.Render(tree, view, samples));
    return frames;
  }

  static Pooled Pool(const std::vector<LodFrame>& frames, const std::vector<LodFrame>& references) {
    Pooled pooled;
    for (size_t v = 0; v < frames.size(); ++v) AddView(pooled, frames[v], references[v].foreground);
    return pooled;
  }

  // Neubert's preprocessing: the PR-optimal scale for each size's lambda, on the input views at
  // that size. (The paper tabulates over lambda alone, PR being invariant to screen size for its
  // renderer; here alpha-tested leaves lose coverage in coarse mip levels, so it is not.)
  // Both orders: the random one (neubert) and the rendering priority (neubert-priority).
  void SearchOptimalScales(LodBenchResult& result, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    for (size_t s = 0; s < options_.sizes.size(); ++s) {
      const int size = options_.sizes[s];
      progress.Step("neubert scales", s, options_.sizes.size());
      for (const char* method : {"neubert", "neubert-priority"}) {
        if (optimal_scale_.count({method, size})) continue;
        const ScaleSearch search = SearchScale(method, size, lambdas_[s]);
        optimal_scale_[{method, size}] = search.best.area_scale;
        result.scale_searches.push_back(search);
      }
    }
    progress.Step("neubert scales", options_.sizes.size(), options_.sizes.size());
    result.preprocess_seconds = SecondsSince(start);
  }

  const std::vector<uint32_t>& OrderOf(const std::string& method) const {
    return method.starts_with("neubert-") ? priority_order_ : order_;
  }

  // The PR of every candidate scale at `lambda` in the method's order, on the input views at `size`.
  ScaleSearch SearchScale(const std::string& method, int size, double lambda) {
    const std::vector<View> at = AtSize(TrainingViews(), size);
    const std::vector<LodFrame>& references = TrainingReferences(size);
    ScaleSearch search;
    search.method = method;
    search.size = size;
    search.lambda = lambda;
    for (double scale : CandidateAreaScales(lambda)) {
      const StudioTreeRenderer tree(BuildPrunedMesh(mesh_, leaves_, PruneLeaves(OrderOf(method), lambda, scale)));
      const Pooled pooled = Pool(RenderAll(tree, at, supersample_), references);
      search.trials.push_back({scale, pooled.coverage.Precision(), pooled.coverage.Recall()});
    }
    search.best = BestScaleTrial(search.trials);
    return search;
  }

  // Neubert's rendering priority (sec. 3): the combined order, in place of the random one.
  void OrderByPriority(LodBenchResult& result, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    progress.Say("neubert priority", Str("ordering ", leaves_.size(), " leaves"));
    RenderingPriorityOptions priority = options_.priority;
    priority.seed = options_.seed;
    priority_order_ = RenderingPriorityOrder(mesh_, leaves_, priority);
    result.priority_seconds = SecondsSince(start);
  }

  // Neubert's detail level selection (sec. 2.5) at each size: the target is the quality of Cook's
  // pruning there (random order, s = 1 / lambda, on the input views); the priority order with its
  // PR-optimal scale is tried at the paper's sample lambdas, walking down from Cook's lambda while
  // the target is met (up while it is not), and the smallest lambda meeting it is interpolated.
  void SelectDetailLevels(LodBenchResult& result, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> grid = DetailLevelLambdas(options_.min_lambda);
    for (size_t s = 0; s < options_.sizes.size(); ++s) {
      const int size = options_.sizes[s];
      progress.Step("neubert levels", s, options_.sizes.size());
      if (matched_level_.count(size)) continue;
      LevelSelection selection;
      selection.size = size;
      selection.cook_lambda = lambdas_[s];
      const ScaleSearch* cook = nullptr;
      const ScaleSearch* priority = nullptr;
      for (const ScaleSearch& search : result.scale_searches)
        if (search.size == size) (search.method == "neubert" ? cook : priority) = &search;
      const ScaleTrial& at_cook = NearestTrial(cook->trials, CookAreaScale(selection.cook_lambda));
      selection.target = PrScore(at_cook.precision, at_cook.recall);
      const auto sample = [](const ScaleSearch& search) {
        return LevelSample{search.lambda, search.best.area_scale, PrScore(search.best.precision, search.best.recall)};
      };
      selection.samples.push_back(sample(*priority));
      if (selection.target < 1) {  // at lambda 1 nothing less than the full mesh matches it
        const bool down = selection.samples.front().quality >= selection.target;
        std::vector<double> walk;
        for (double lambda : grid)
          if (down ? lambda < selection.cook_lambda - 1e-9 : lambda > selection.cook_lambda + 1e-9)
            walk.push_back(lambda);
        if (down) std::reverse(walk.begin(), walk.end());
        for (double lambda : walk) {
          selection.samples.push_back(sample(SearchScale("neubert-matched", size, lambda)));
          if ((selection.samples.back().quality >= selection.target) != down) break;
        }
      }
      selection.matched = QualityMatchedLevel(selection.samples, selection.target);
      matched_level_[size] = selection.matched;
      result.level_selections.push_back(selection);
    }
    progress.Step("neubert levels", options_.sizes.size(), options_.sizes.size());
    result.level_selection_seconds = SecondsSince(start);
  }

  // The VMI removal sequence, down to the fewest leaves any size keeps, from the input views.
  void RankByVmi(LodBenchResult& result, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    progress.Say("vmi", Str("ranking ", leaves_.size(), " leaves from ", rig_.inputs.size(), " views"));
    size_t keep = leaves_.size();
    for (double lambda : lambdas_) keep = std::min(keep, KeptLeafCount(leaves_.size(), lambda));
    LeafIdRenderer ids(mesh_, leaves_);
    vmi_sequence_ = VmiRemovalSequence(ids, leaves_.size(), AtSize(rig_.inputs, kVmiSize), keep);
    result.vmi_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // The preprocessing steps' views: up to `preprocess_views` of the studio's input views, spread
  // evenly, so that no method is tuned on the views it is scored on.
  std::vector<View> TrainingViews() const {
    std::vector<View> training;
    const size_t step = std::max<size_t>(1, rig_.inputs.size() / options_.preprocess_views);
    for (size_t i = 0; i < rig_.inputs.size() && training.size() < static_cast<size_t>(options_.preprocess_views);
         i += step)
      training.push_back(rig_.inputs[i]);
    return training;
  }

  // The full mesh at the training views at `size`, rendered once for every step that needs it.
  const std::vector<LodFrame>& TrainingReferences(int size) {
    auto it = training_references_.find(size);
    if (it == training_references_.end())
      it = training_references_
               .emplace(size, RenderAll(full_, AtSize(TrainingViews(), size), ReferenceSupersample(size)))
               .first;
    return it->second;
  }

  // Clasen et al. calibrate the ellipsoids' size by image error: the scale of the semi-axes with
  // the least multi-scale RMS against the full mesh on the training views, here at each size for
  // the level that size draws.
  double CalibrateEllipsoids(int size, const EllipsoidLevel& level, const std::vector<LinePrimitive>& lines,
                             LodBenchResult& result) {
    const auto key = std::make_pair(size, level.clusters);
    if (const auto it = ellipsoid_scale_.find(key); it != ellipsoid_scale_.end()) return it->second;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<View> at = AtSize(TrainingViews(), size);
    const std::vector<LodFrame>& references = TrainingReferences(size);
    EllipsoidCalibration calibration;
    calibration.size = size;
    calibration.clusters = level.clusters;
    calibration.ms_rms = std::numeric_limits<double>::infinity();
    PrimitiveDrawOptions draw;
    draw.min_line_pixels = kClasenLinePixels;
    for (double scale : kEllipsoidScales) {
      const PrimitiveRenderer drawn(
          {}, lines, crown_.first, crown_.second,
          EllipsoidSurface(ScaledEllipsoids(level.ellipsoids, scale), options_.ellipsoids.sphere_segments));
      const Pooled pooled = Pool(RenderPrimitives(drawn, draw, at), references);
      const double ms_rms = pooled.multiscale_rms / std::max(pooled.views, 1);
      calibration.trials.emplace_back(scale, ms_rms);
      if (ms_rms < calibration.ms_rms) calibration.ms_rms = ms_rms, calibration.scale = scale;
    }
    result.ellipsoid_calibrations.push_back(calibration);
    result.ellipsoid_calibration_seconds += SecondsSince(start);
    return ellipsoid_scale_[key] = calibration.scale;
  }

  // The primitive methods' preprocessing: the branch skeleton, the points, the EM fits and the
  // line merges. Each builds what the mesh has of leaves and bark and says what it cannot.
  void BuildPrimitives(LodBenchResult& result, Progress& progress) {
    auto start = std::chrono::steady_clock::now();
    skeleton_ = ExtractBranchSkeleton(mesh_);
    result.skeleton_seconds = SecondsSince(start);
    if (leaves_.empty() && skeleton_.SegmentCount() == 0) {
      result.notes.push_back(
          "the mesh has no leaves and too little bark for a branch line: points and ellipsoids were not measured");
      return;
    }
    if (leaves_.empty())
      result.notes.push_back("points and ellipsoids: no leaves, so no points and no ellipsoids; only branch lines");
    if (skeleton_.SegmentCount() == 0)
      result.notes.push_back("points and ellipsoids: no bark to make branch lines of; only the leaves' primitives");
    progress.Say("points", Str("sampling ", leaves_.size(), " leaves; ", skeleton_.SegmentCount(), " branch segments"));
    start = std::chrono::steady_clock::now();
    point_lines_ = BuildPointLineHierarchy(mesh_, leaves_, skeleton_, options_.points);
    result.points_seconds = SecondsSince(start);
    result.sampled_points = point_lines_.points.size();
    result.skeleton_segments = skeleton_.SegmentCount();
    progress.Say("ellipsoids",
                 Str("EM on ", leaves_.size(), " leaves, up to ", options_.ellipsoids.max_clusters, " clusters"));
    start = std::chrono::steady_clock::now();
    ellipsoid_levels_ = BuildEllipsoidHierarchy(leaves_, LeafColours(mesh_, leaves_), options_.ellipsoids);
    result.ellipsoid_seconds = SecondsSince(start);
    start = std::chrono::steady_clock::now();
    line_hierarchy_ = SimplifyLines(skeleton_);
    result.line_merge_seconds = SecondsSince(start);
    for (const EllipsoidLevel& level : ellipsoid_levels_) {
      result.ellipsoid_levels.push_back(level.clusters);
      result.ellipsoid_counts.push_back(level.ellipsoids.size());
    }
    result.methods.insert(result.methods.end(), {"points", "ellipsoids"});
  }

  // Pixels per mesh unit at the tree's distance, the views' mean: what sizes a primitive.
  double PixelsPerUnit(const std::vector<View>& at) const {
    double sum = 0;
    for (const View& view : at) sum += view.camera.FocalY() / std::max((view.pose.Center() - rig_.target).norm(), 1e-9);
    return sum / static_cast<double>(std::max<size_t>(at.size(), 1));
  }

  std::vector<LodFrame> RenderPrimitives(const PrimitiveRenderer& drawn, const PrimitiveDrawOptions& draw,
                                         const std::vector<View>& at) {
    std::vector<LodFrame> frames;
    for (const View& view : at)
      frames.push_back(renderer_.Render([&](const View& v, const StudioLighting& lighting, double near,
                                            double far) { drawn.Draw(v, lighting, near, far, draw); },
                                        view, supersample_));
    return frames;
  }

  // Deussen et al.: the prefix of points and lines the size asks for, or the mesh when it asks
  // for more points than were sampled.
  LodBenchRow MeasurePoints(int size, const std::vector<View>& at, const std::vector<LodFrame>& references) {
    LodBenchRow row;
    row.method = "points";
    row.size = size;
    const PointLineLevel level = PointLineLevelFor(point_lines_, PixelsPerUnit(at), options_.points);
    std::vector<LodFrame> frames;
    if (level.polygons) {
      row.leaves = leaves_.size();
      row.triangles = mesh_.TriangleCount();
      row.geometry_bytes = GeometryBytes(mesh_);
      row.texture_bytes = TextureBytes(mesh_);
      frames = ReferenceSupersample(size) == supersample_ ? references : RenderAll(full_, at, supersample_);
    } else {
      const PointLineHierarchy prefix = PointLinePrefix(point_lines_, level.points, level.lines);
      const PrimitiveRenderer drawn(prefix.points, prefix.lines, crown_.first, crown_.second);
      PrimitiveDrawOptions draw;
      draw.point_pixels = level.point_pixels;
      draw.min_line_pixels = static_cast<float>(options_.points.min_line_pixels);
      frames = RenderPrimitives(drawn, draw, at);
      row.leaves = 0;
      row.lambda = static_cast<double>(prefix.points.size()) /
                   static_cast<double>(std::max<size_t>(point_lines_.points.size(), 1));
      row.primitives = prefix.points.size() + prefix.lines.size();
      row.triangles = 2 * prefix.lines.size();
      row.geometry_bytes = drawn.GpuBytes();
    }
    Keep(row, frames.front().foreground, /*straight=*/false);
    FillQuality(row, Pool(frames, references));
    return row;
  }

  // Clasen et al.: the level of ellipsoids whose mean diameter stays above min_pixels, and the
  // branch lines merged while a merge moves them less than a pixel.
  LodBenchRow MeasureEllipsoids(int size, const std::vector<View>& at, const std::vector<LodFrame>& references,
                                LodBenchResult& result) {
    LodBenchRow row;
    row.method = "ellipsoids";
    row.size = size;
    row.leaves = 0;
    const double pixels_per_unit = PixelsPerUnit(at);
    const std::vector<LinePrimitive> lines =
        SkeletonLines(LinesAfter(line_hierarchy_, MergesWithin(line_hierarchy_, 1 / pixels_per_unit)));
    std::vector<PointPrimitive> surface;
    size_t ellipsoids = 0;
    if (!ellipsoid_levels_.empty()) {
      const EllipsoidLevel& level =
          ellipsoid_levels_[EllipsoidLevelFor(ellipsoid_levels_, pixels_per_unit, options_.ellipsoids.min_pixels)];
      row.level = level.clusters;
      row.area_scale = CalibrateEllipsoids(size, level, lines, result);
      ellipsoids = level.ellipsoids.size();
      surface =
          EllipsoidSurface(ScaledEllipsoids(level.ellipsoids, row.area_scale), options_.ellipsoids.sphere_segments);
    }
    const PrimitiveRenderer drawn({}, lines, crown_.first, crown_.second, surface);
    PrimitiveDrawOptions draw;
    draw.min_line_pixels = kClasenLinePixels;
    const std::vector<LodFrame> frames = RenderPrimitives(drawn, draw, at);
    row.primitives = ellipsoids + lines.size();
    row.triangles = surface.size() / 3 + 2 * lines.size();
    row.geometry_bytes = drawn.GpuBytes();
    Keep(row, frames.front().foreground, /*straight=*/false);
    FillQuality(row, Pool(frames, references));
    return row;
  }

  // The leaves a pruning method draws at `lambda`, and the area scale the row reports.
  std::vector<LeafDraw> Draws(const std::string& method, int size, double lambda, double* area_scale) const {
    if (method == "vmi") {
      std::vector<LeafDraw> draws =
          VmiLeafDraws(leaves_, vmi_sequence_, leaves_.size() - KeptLeafCount(leaves_.size(), lambda));
      double sum = 0;
      for (const LeafDraw& draw : draws) sum += draw.area_scale;
      *area_scale = sum / static_cast<double>(std::max<size_t>(draws.size(), 1));  // mean: each leaf has its own
      return draws;
    }
    *area_scale = method == "pruned"                                          ? 1.0
                  : method == "cook"                                          ? CookAreaScale(lambda)
                  : method == "neubert-matched" || method == "neubert-colour" ? matched_level_.at(size).area_scale
                                                                              : optimal_scale_.at({method, size});
    return PruneLeaves(OrderOf(method), lambda, *area_scale);
  }

  LodBenchRow MeasureMethod(const std::string& method, int size, double lambda, const std::vector<View>& at,
                            const std::vector<LodFrame>& references) {
    LodBenchRow row;
    row.method = method;
    row.size = size;
    std::vector<LodFrame> frames;
    TreeMesh pruned;
    const TreeMesh* drawn = &mesh_;
    if (method == "full") {
      row.leaves = leaves_.size();
      frames = ReferenceSupersample(size) == supersample_ ? references : RenderAll(full_, at, supersample_);
    } else {
      row.lambda = method == "neubert-matched" || method == "neubert-colour" ? matched_level_.at(size).lambda : lambda;
      const std::vector<LeafDraw> draws = Draws(method, size, row.lambda, &row.area_scale);
      row.leaves = draws.size();
      pruned = method == "neubert-colour" ? BuildPrunedMesh(RecolouredMesh(draws, row.lambda), leaves_, draws)
                                          : BuildPrunedMesh(mesh_, leaves_, draws);
      drawn = &pruned;
      const StudioTreeRenderer tree(pruned);
      frames = RenderAll(tree, at, supersample_);
    }
    row.triangles = drawn->TriangleCount();
    row.geometry_bytes = GeometryBytes(*drawn);
    row.texture_bytes = TextureBytes(mesh_);
    Keep(row, frames.front().foreground, /*straight=*/false);
    FillQuality(row, Pool(frames, references));
    return row;
  }

  // Neubert's sec. 5 and Cook's contrast correction: the survivors' colours matched to the full
  // tree's mean and, by sqrt(lambda), to its pixels' variance.
  TreeMesh RecolouredMesh(const std::vector<LeafDraw>& draws, double lambda) {
    if (leaf_colours_.empty()) leaf_colours_ = LeafColours(mesh_, leaves_);
    return WithLeafColours(mesh_, leaves_, draws, leaf_colours_,
                           CorrectedLeafColours(leaf_colours_, leaves_, draws, ContrastFactor(lambda)));
  }

  LodBenchRow MeasureAsset(int size, const std::vector<View>& at, const std::vector<LodFrame>& references) {
    LodBenchRow row;
    row.method = "asset";
    row.size = size;
    TreeRenderOptions render_options;
    render_options.lod_history = false;  // every view on its own, independent of the order
    Pooled pooled;
    size_t cells = 0;
    for (size_t v = 0; v < at.size(); ++v) {
      FrameStats stats;
      LodFrame frame;
      frame.foreground = asset_->Render(at[v], render_options, &stats);
      frame.draw_ms = stats.frame_ms;
      cells += stats.cells;
      AddView(pooled, frame, references[v].foreground, /*straight=*/true);
      if (v == 0) Keep(row, frame.foreground, /*straight=*/true);
    }
    row.triangles = 2 * cells / std::max<size_t>(at.size(), 1);
    row.geometry_bytes = asset_->GpuBytes().buffers;
    row.texture_bytes = asset_->GpuBytes().atlas;
    FillQuality(row, pooled);
    row.fragments = -1;  // not measured for the asset renderer
    return row;
  }

  const LodBenchOptions& options_;
  const TreeMesh& mesh_;
  const std::vector<Leaf> leaves_;
  const std::vector<uint32_t> order_;
  const int frame_, supersample_;
  std::vector<double> lambdas_;  // per size
  const std::pair<Eigen::Vector3d, Eigen::Vector3d> draw_bounds_;
  LodViewRenderer renderer_;  // its GL context is current for every GL object below
  const StudioRig rig_;
  const std::vector<View> views_;
  const StudioTreeRenderer full_;
  std::vector<uint32_t> priority_order_;                         // Neubert's rendering priority
  std::map<std::pair<std::string, int>, double> optimal_scale_;  // by method and size
  std::map<int, LevelSample> matched_level_;                     // neubert-matched, by size
  std::vector<Eigen::Vector3f> leaf_colours_;                    // every leaf's, for neubert-colour
  std::map<int, std::vector<LodFrame>> training_references_;     // by size
  std::map<std::pair<int, int>, double> ellipsoid_scale_;        // by size and clusters
  std::vector<VmiRemoval> vmi_sequence_;
  std::unique_ptr<TreeRenderer> asset_;
  const std::pair<Eigen::Vector3f, Eigen::Vector3f> crown_;
  BranchSkeleton skeleton_;
  PointLineHierarchy point_lines_;
  std::vector<EllipsoidLevel> ellipsoid_levels_;
  LineHierarchy line_hierarchy_;
  std::vector<SavedView> saved_views_;
};

}  // namespace

LodBenchResult RunLodBench(const TreeMesh& mesh, const std::string& tree_name, const LodBenchOptions& options,
                           Progress& progress) {
  options.Check();
  mesh.Check();
  LodBench bench(mesh, options);
  return bench.Run(tree_name, progress);
}

}  // namespace voltree
