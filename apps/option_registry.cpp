#include "apps/option_registry.h"

#include <stdexcept>

namespace voltree::app {
namespace {

// Commands' own.
std::vector<OptionSpec> CommandFlags() {
  return {
      {"-o,--output", {}, "Where to write", true},
      {"--force", {}, "Replace what an earlier run wrote", true},
      {"--quiet", {}, "No progress lines"},
      {"--threads",
       {"ReconstructOptions.threads", "MatteWorkspaceOptions.threads"},
       "Worker threads (0: all cores); the output does not depend on them"},
  };
}

// The tree photographed (synth, demo).
std::vector<OptionSpec> TreeFlags() {
  return {
      {"--tree", {"TreeSource.tree"}, "A preset (oak, pine, young-oak) or a mesh file (.gltf, .glb, .obj)"},
      {"--seed",
       {"TreeSource.seed", "StudioOptions.seed"},
       "Seed of the procedural tree, the ground, sky and clutter, and the rings' rotation"},
      {"--mesh-up", {"TreeSource.up"}, "Up axis of a mesh file: y (glTF convention) or z"},
  };
}

// The photo studio (synth, demo).
std::vector<OptionSpec> StudioFlags() {
  return {
      {"--views", {"StudioOptions.views"}, "Input photos, spread over the camera rings"},
      {"--held-out", {"StudioOptions.held_out"}, "Held-out truth views, between the rings at other azimuths"},
      {"--rings", {"StudioOptions.rings"}, "Camera rings at elevations from --min-elevation to 35 degrees"},
      {"--size",
       {"StudioOptions.width", "StudioOptions.height", "RenderJobOptions.width", "RenderJobOptions.height",
        "ViewerOptions.width", "ViewerOptions.height"},
       "Image size WIDTHxHEIGHT in pixels, or one number for a square"},
      {"--supersample", {"StudioOptions.supersample"}, "Samples per pixel and axis (mattes get 1/S^2 alpha steps)"},
      {"--camera",
       {"StudioOptions.camera_model"},
       "Camera model of the photos: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL or OPENCV"},
      {"--distortion",
       {"StudioOptions.distortion"},
       "Comma-separated distortion parameters of the camera model (SIMPLE_RADIAL: k; RADIAL: k1,k2; OPENCV: "
       "k1,k2,p1,p2); default none"},
      {"--fov", {"StudioOptions.fov_degrees"}, "Field of view across the smaller image side, degrees"},
      {"--min-elevation",
       {"StudioOptions.min_elevation_degrees"},
       "Elevation of the lowest camera ring in degrees, seen from the middle of the tree's bounds (the highest is "
       "35); 5 looks almost level at the tree, as a person holding the camera would"},
      {"--backdrop",
       {"StudioOptions.backdrop"},
       "What stands behind the tree: realistic (a place: skyline, bushes, rocks, other trees) or plain (sky and "
       "textured ground only); mattes and truth are the tree's alone either way"},
  };
}

// Calibration (calibrate, run).
std::vector<OptionSpec> CalibrateFlags() {
  return {
      {"--camera-model",
       {"CalibrateOptions.camera_model"},
       "COLMAP camera model shared by all photos: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV"},
      {"--camera-params",
       {"CalibrateOptions.camera_params"},
       "Known intrinsics in COLMAP's order, comma separated (e.g. PINHOLE: fx,fy,cx,cy); kept fixed"},
      {"--max-image-size", {"CalibrateOptions.max_image_size"}, "COLMAP feature extraction: longest side in pixels"},
      {"--max-features",
       {"CalibrateOptions.max_features"},
       "COLMAP feature extraction: SIFT features per photo at most"},
      {"--matcher",
       {"CalibrateOptions.matcher"},
       "COLMAP matcher: exhaustive, or sequential for photos taken in order along a walk"},
      {"--min-registered", {"CalibrateOptions.min_registered"}, "Fraction of the photos that must get a camera"},
      {"--robust-loss",
       {"RobustAdjustOptions.loss_scale"},
       "After COLMAP's mapper: bundle adjustment under a Cauchy loss of this scale in pixels, so that "
       "observations on leaf edges and crossing branches do not pull the cameras (0: keep the mapper's model)"},
      {"--mask",
       {"CalibrateOptions.mask"},
       "Where features may come from when mattes/ exists: all (ground and surroundings help), tree (the tree "
       "only), near (the tree and a band around it)"},
      {"--up", {"CalibrateOptions.up"}, "World up direction x,y,z in COLMAP's frame (default: from the cameras)"},
      {"--height", {"CalibrateOptions.height_metres"}, "Tree height in metres: scale the scene to metres"},
      {"--import",
       {"CalibrateOptions.import_model"},
       "Use this existing COLMAP model (text or binary) instead of running COLMAP; it is normalized"},
      {"--known-cameras",
       {"CalibrateOptions.known_cameras"},
       "Use this COLMAP model (text or binary) as is: its cameras are already in the tree frame, metres"},
      {"--hull-resolution",
       {"HullOptions.resolution"},
       "Voxels along the longest side of the visual hull that bounds the tree"},
      {"--no-affine",
       {"CalibrateOptions.affine_features"},
       "Plain SIFT instead of affine-covariant SIFT (faster; photos from low and high rings then rarely match)"},
      {"--no-guided",
       {"CalibrateOptions.guided_matching"},
       "No guided matching (re-matching under the found geometry)"},
  };
}

// Matting (matte, run).
std::vector<OptionSpec> MatteFlags() {
  return {
      {"--refine",
       {"MatteOptions.refine"},
       "How the unknown band of a matte is solved: infoflow (OpenCV alphamat, most accurate), guided (guided "
       "filter, fastest), none (first estimate only)"},
      {"--horizon",
       {"MatteOptions.horizon"},
       "Horizon row as a fraction of the photo height from the top (0..1); default: estimated"},
      {"--band", {"MatteOptions.band_radius"}, "Unknown band half-width in pixels around ground edges (0: auto)"},
      {"--mattes",
       {"MatteWorkspaceOptions.user_mattes"},
       "Use these mattes instead (folder of PNG alpha or grey images named like the photos); they are checked, "
       "converted and their foreground colours computed"},
  };
}

// Reconstruction (reconstruct, run, demo).
std::vector<OptionSpec> ReconstructFlags() {
  return {
      {"--levels",
       {"ReconstructOptions.levels"},
       "Octree levels: level 0 is the root, the finest has branching^(levels-1) cells per axis; auto: as many as "
       "the photos fill (a finest texel covers about one photo pixel). Not given to run or demo: 7, and more where "
       "the photos fill them and the asset is predicted to fit --max-bytes (a sparse tree)"},
      {"--branching",
       {"ReconstructOptions.branching"},
       "Cells per axis per subdivision: 2 (octree) or 3 (tri-grid, Reche 2004)"},
      {"--texels", {"ReconstructOptions.texels"}, "Billboard textures are texels x texels (8 in Reche 2004)"},
      {"--margin",
       {"ReconstructOptions.margin"},
       "Root cube margin per side, as a fraction of the bounds' largest extent"},
      {"--carve-alpha",
       {"ReconstructOptions.carve_alpha"},
       "Alpha at or below which a pixel is empty for visual-hull carving"},
      {"--carve-views",
       {"OpacityOptions.carve_views"},
       "Carve a cell when this many photos each see it empty (1: the strict visual hull; 2 survives one "
       "wrong matte, such as a thin trunk cut off in one photo, but blurs a dense crown's edge)"},
      {"--solver",
       {"OpacityOptions.solver"},
       "Opacity solver: sart (streamed SART) or ceres (bounded least squares, small volumes only)"},
      {"--iterations",
       {"SartOptions.iterations"},
       "SART iterations per level (150 runs to convergence: fewer leave sigma spread over cells the photos leave "
       "empty)"},
      {"--relaxation", {"SartOptions.relaxation"}, "SART relaxation lambda, in (0, 2)"},
      {"--ceres-iterations", {"CeresSolveOptions.iterations"}, "Ceres iterations per level (--solver ceres)"},
      {"--huber",
       {"CeresSolveOptions.huber"},
       "Huber loss scale on the weighted ray residual (--solver ceres; 0: none)"},
      {"--refine-depth",
       {"OpacityOptions.refine_min_optical_depth"},
       "Refine a cell only when sigma x cell edge (its optical depth) reaches this (0: every cell the visual hull "
       "keeps)"},
      {"--prune",
       {"BillboardOptions.prune"},
       "Hide a texel when the alpha accumulated in front of its cell exceeds this (lower drops more billboards: "
       "0.95 makes the demo oak's volume a fifth smaller and about 0.6 dB worse from new viewpoints; 1 hides "
       "nothing, and a texel behind an opaque front then takes the front's colour)"},
      {"--billboard-scale",
       {"BillboardOptions.scale", "BillboardFitOptions.billboard_scale", "TreeRenderOptions.billboard_scale"},
       "Billboard side / cell edge (render: as given to reconstruct)"},
      {"--no-fit",
       {"BillboardFitOptions.enabled"},
       "Keep the tomography's billboards: do not fit them to the photos (faster; to compare)"},
      {"--fit-iterations",
       {"BillboardFitOptions.iterations"},
       "Gauss-Newton steps of the billboard fit per level and view"},
      {"--fit-prior",
       {"BillboardFitOptions.prior"},
       "How strongly the billboard fit keeps the tomography's texels where the photos do not decide"},
      {"--fit-neighbours",
       {"BillboardFitOptions.neighbours"},
       "Also fit each view's billboards to this many nearest photos, where the renderer blends them"},
      {"--fit-neighbour-weight",
       {"BillboardFitOptions.neighbour_weight"},
       "Weight of each neighbouring photo against the view's own in the billboard fit"},
  };
}

// Compression (compress, run, demo).
std::vector<OptionSpec> CompressFlags() {
  return {
      {"--codebook",
       {"CompressOptions.colour_codebook"},
       "Colour codebook size (codewords of texels x texels), the largest tried: both codebooks are halved "
       "while the asset exceeds --max-bytes"},
      {"--alpha-codebook", {"CompressOptions.alpha_codebook"}, "Alpha codebook size, the largest tried"},
      {"--max-bytes",
       {"CompressOptions.max_bytes"},
       "Budget of the asset on disk, e.g. 1MiB or 500KiB (0: none): both codebooks are halved, down to 64, "
       "until it fits, then colour codewords are traded for alpha ones where the texture PSNR gains (the demo oak: "
       "16 / 1024; a sparse tree fits 2048 / 2048)"},
      {"--space", {"CompressOptions.space"}, "Colour space of the colour codebook: lab or rgb"},
      {"--gla",
       {"CompressOptions.colour_rule"},
       "Codeword rule of the colour codebook: classic (the cluster's centroid) or modified (its member closest "
       "to the centroid, Linz 2006; up to 0.8 dB RGB worse at the input views)"},
      {"--alpha-gla",
       {"CompressOptions.alpha_rule"},
       "Codeword rule of the alpha codebook: modified (the cluster's member closest to its centroid, Linz 2006) "
       "or classic (the centroid; 0.6 dB alpha worse at the demo oak's input views)"},
      {"--no-alpha-weighted",
       {"CompressOptions.alpha_weighted"},
       "Measure colour distances without weighting each texel by its alpha, so that texels a billboard does not "
       "draw steer its codeword too (Linz 2006; 0.4 dB RGB worse at the input views, and faster)"},
      {"--no-codebook-trade",
       {"CompressOptions.trade_codebooks"},
       "Under --max-bytes, keep both codebooks the same size instead of trading colour codewords for alpha ones "
       "where the texture PSNR gains (the demo oak: 16 / 1024 instead of 64 / 64)"},
      {"--gla-tolerance", {"CompressOptions.tolerance"}, "Stop GLA when the relative distortion drop is below this"},
      {"--gla-iterations", {"CompressOptions.max_iterations"}, "At most this many GLA iterations"},
      {"--gla-seed", {"CompressOptions.seed"}, "Seed of the codebooks' k-means++ initialization"},
      {"--no-zstd",
       {"CompressOptions.zstd"},
       "Store the asset's chunks raw instead of zstd-compressed (7-17 % larger on the demo oak; what the web page "
       "reads, "
       "which 'voltree web' writes itself)"},
  };
}

// Renders (render, run, demo).
std::vector<OptionSpec> RenderFlags() {
  return {
      {"--orbit",
       {"OrbitFramesOptions.frames", "RenderJobOptions.orbit"},
       "Frames on a circle about the tree at the input views' mean distance and elevation (run, demo: into "
       "report/orbit/, 0: none)"},
      {"--orbit-size", {"OrbitFramesOptions.size"}, "Orbit frame side in pixels (square)"},
      {"--cameras",
       {"RenderJobOptions.cameras"},
       "COLMAP text model folder (cameras.txt, images.txt); each frame is named after its image"},
      {"--assets",
       {"RenderJobOptions.asset_folder", "ViewerOptions.asset_folder", "WebPageOptions.asset_folder"},
       "Scenes: folder to look their assets up in (default: the scene's folder)"},
      {"--level", {"LodOptions.forced_level"}, "Draw only this octree level (default: LOD)"},
      {"--stats",
       {"TreeRenderOptions.count_fragments"},
       "Also count the fragments each frame costs (fragment shader invocations, GL_ARB_pipeline_statistics_query; "
       "says so where the driver cannot count them)"},
      {"--max-level",
       {"RenderJobOptions.max_level"},
       "Load the asset's levels 0..K only (progressive: what the first bytes of the file draw); beyond the asset's "
       "finest level: all, with a note (default: all)"},
      {"--lod",
       {"LodOptions.rule", "MeshLodOptions.method"},
       "LOD of .vtree assets, the rule: screen (Euclidean distance to each cell) or planes (Linz 2006: depth along "
       "the view direction); of a scene's meshes (its meshes field), lod-bench's method per instance at the level "
       "its screen size picks: mesh (the full mesh), points (Deussen 2002), ellipsoids (Clasen), cook "
       "(stochastic pruning) or neubert (Neubert 2011: cook's lambda in rendering-priority order, times the "
       "visible fraction of the crown in the previous frame's depth), the full mesh where the tree is near"},
      {"--full-pixels",
       {"MeshLodOptions.full_pixels"},
       "--lod cook, neubert and ellipsoids: trees at least this many pixels tall on screen are drawn as the full "
       "mesh; cook and neubert keep lambda = (height / this)^2 of the leaves below it"},
      {"--texel-pixels",
       {"LodOptions.max_texel_pixels"},
       "LOD: descend while a billboard texel covers more pixels than this"},
      {"--tint-levels", {"TreeRenderOptions.tint_levels"}, "Colour billboards by octree level (to see the LOD)"},
      {"--no-trim",
       {"TreeRenderOptions.trim_quads"},
       "Draw each billboard's whole camera-facing quad, and billboards whose alpha is 0 everywhere, instead of "
       "quads trimmed to where the alpha can be non-zero (the same image: to measure what trimming saves with "
       "--stats)"},
      {"--background",
       {"TreeRenderOptions.background", "ViewerOptions.background"},
       "Background colour R,G,B 0..255, opaque"},
      {"--turntable",
       {"RenderJobOptions.turntable"},
       "Also (or only) encode the orbit frames as an H.264 .mp4 at 30 fps over the background (grey when "
       "transparent); needs ffmpeg"},
  };
}

// Whole runs (run, demo).
std::vector<OptionSpec> RunFlags() {
  return {
      {"--no-guards",
       {"RunOptions.guards"},
       "Skip the guards that stop a run, writing no asset, when mattes cover most of a photo or almost nothing, "
       "disagree with each other through the cameras, or are not reproduced by the reconstruction (to inspect "
       "what such input gives)"},
      {"--no-eval", {"DemoOptions.evaluate"}, "Skip the evaluation report (default: evaluate)"},
      {"--colmap",
       {"DemoOptions.colmap"},
       "Calibrate the photos with COLMAP (SIFT on the CPU, about a minute) instead of using the studio's true "
       "cameras; the true input cameras are kept in truth/input_sparse/ and the held-out cameras are moved into "
       "COLMAP's frame by the similarity fitted between the two, so the evaluation includes calibration error; the "
       "lower camera ring is raised to 20 degrees, as COLMAP registers grazing views of the ground poorly (default: "
       "true cameras)"},
      {"--recheck",
       {},
       "Check the existing mattes against each other through the cameras in sparse/ and matte again, inside the "
       "visual hull of the others, the photos that disagree (what 'run' does with photos alone); their mattes and "
       "foregrounds are replaced, and the tree's bounds in scene.json are found again from the new mattes (unless the "
       "studio wrote them: those are the true bounds)"},
  };
}

// Many workspaces (batch, scene).
std::vector<OptionSpec> BatchFlags() {
  return {
      {"-j,--jobs",
       {"BatchOptions.jobs"},
       "Jobs at once; on this machine its cores are shared between them (with --profile: jobs queued at once; "
       "default: the profile's)"},
      {"--profile",
       {"BatchOptions.profile"},
       "Snakemake profile (a folder with config.yaml, or a name in ~/.config/snakemake/) that sends the jobs to a "
       "cluster"},
      {"-n,--dry-run", {"BatchOptions.dry_run"}, "Print the jobs that would run and the captures' state; run nothing"},
      {"--positions", {"SceneLayoutOptions.positions"}, "Survey CSV: tree, x, y[, rotation][, scale]"},
      {"--spacing",
       {"SceneLayoutOptions.spacing"},
       "Grid spacing in the assets' units (0: 1.25 times the widest asset's footprint)"},
  };
}

// The desktop viewer (view).
std::vector<OptionSpec> ViewerFlags() {
  return {
      {"--unpruned",
       {"ViewerOptions.unpruned"},
       "The same capture's asset built without pruning (reconstruct --prune 1, then compress); U switches to it "
       "and back"},
      {"--script",
       {"ViewerOptions.script"},
       "Scripted events, one a line: SECONDS drag|pan DX DY, scroll STEPS, key K, screenshot, quit; the session ends "
       "after the last one"},
      {"--no-panel", {"ViewerOptions.panel"}, "No statistics panel"},
  };
}

// Evaluation (eval, run).
std::vector<OptionSpec> EvaluateFlags() {
  return {
      {"--grey",
       {"ImageMetricsOptions.background_grey"},
       "Grey (0..255) that truth and render are composited over for the RGB metrics"},
      {"--distance",
       {"EvaluateOptions.distance"},
       "Judge the asset from this many times the cameras' distance: renders at 1/K of the photos' size, so the "
       "LOD draws what it would there, against the truth area-resampled to it (1.6: the demo oak a third of the "
       "frame's height)"},
      {"--eval-levels",
       {"EvaluateOptions.each_level"},
       "Which renders eval measures: all (the renderer's LOD and each octree level forced) or auto (only the LOD, "
       "faster on large photos)"},
      {"--no-input", {"EvaluateOptions.input_views"}, "Do not evaluate at the input views (default: compare them too)"},
      {"--no-images", {"EvaluateOptions.images"}, "No side-by-side PNGs of the held-out views (default: written)"},
      {"--no-plots", {"EvaluateOptions.plots"}, "Do not run gnuplot (default: plots when gnuplot is installed)"},
      {"--budget",
       {"EvaluateOptions.budget"},
       "Also measure what each step costs (the volume, uncompressed billboards, VQ, DXT5, the LOD) at the input "
       "and held-out views; needs DIR/volume; adds a table to the report and metrics.json"},
      {"--asset",
       {"EvaluateOptions.asset", "LodBenchOptions.asset"},
       "The .vtree asset to measure (eval: default DIR/tree.vtree; lod-bench: drawn as an extra row, none by "
       "default)"},
      {"--report",
       {"EvaluateOptions.report"},
       "Report folder (default: DIR/report); its other files (contact sheet, orbit/) are kept"},
      {"--codebook-sweep",
       {"EvaluateOptions.codebook_sweep"},
       "JSON of PSNR per codebook size to plot (default: REPORT/codebook_sweep.json when it exists)"},
      {"--scene-bench",
       {"EvaluateOptions.scene_bench"},
       "JSON of ms per frame per number of trees to plot (default: REPORT/scene_bench.json when it exists)"},
  };
}

// The LOD bench (lod-bench).
std::vector<OptionSpec> LodBenchFlags() {
  return {
      {"--sizes",
       {"LodBenchOptions.sizes"},
       "Comma-separated screen sizes: the tree framed as in the studio's photos, in an image this many pixels tall "
       "(8 to the frame's height, --size)"},
      {"--min-lambda",
       {"LodBenchOptions.min_lambda", "MeshLodOptions.min_lambda"},
       "The smallest fraction of leaves a size keeps, in (0, 1]; lambda = max(this, (size / frame)^2)"},
      {"--prune-seed",
       {"LodBenchOptions.seed", "MeshLodOptions.seed"},
       "Seed of the leaves' random pruning order (render --lod: also of the points' sampling and the EM start)"},
      {"--priority",
       {"RenderingPriorityOptions.terms"},
       "Neubert's rendering priority for the neubert-priority, -matched and -colour rows: combined (silhouette^2 + "
       "density, the paper's), silhouette or density alone"},
      {"--top-views",
       {"LodBenchOptions.top_views"},
       "Views from 80 degrees above the horizon, besides the held-out ring (0..16)"},
      {"--save-views",
       {"LodBenchOptions.save_views"},
       "Also write the first view of every row and of the reference at each size: views/METHOD_SIZE.png"},
  };
}

// Grouped by the stage whose options they set; within a group, in the order of --help.
std::vector<OptionSpec> MakeRegistry() {
  std::vector<OptionSpec> registry;
  for (auto group : {CommandFlags, TreeFlags, StudioFlags, CalibrateFlags, MatteFlags, ReconstructFlags, CompressFlags,
                     RenderFlags, RunFlags, BatchFlags, ViewerFlags, EvaluateFlags, LodBenchFlags})
    for (OptionSpec& spec : group()) registry.push_back(std::move(spec));
  return registry;
}

// "-o,--output" -> "--output"; "--levels" -> "--levels".
std::string_view LongName(std::string_view flag) {
  const size_t comma = flag.rfind(',');
  return comma == std::string_view::npos ? flag : flag.substr(comma + 1);
}

}  // namespace

const std::vector<OptionSpec>& RegisteredOptions() {
  static const std::vector<OptionSpec> registry = MakeRegistry();  // constant after construction
  return registry;
}

const OptionSpec& RegisteredOption(std::string_view flag) {
  for (const OptionSpec& spec : RegisteredOptions())
    if (spec.flag == flag || LongName(spec.flag) == flag) return spec;
  throw std::logic_error("option " + std::string(flag) + " is not in the option registry");
}

std::string FlagForField(std::string_view field) {
  for (const OptionSpec& spec : RegisteredOptions())
    for (const std::string& f : spec.fields)
      if (f == field) return std::string(LongName(spec.flag));
  return "";
}

std::string DescribeOptionError(const OptionError& error) {
  const std::string flag = FlagForField(error.field());
  return flag.empty() ? error.what() : flag + " " + error.problem();
}

std::string RetiredFlagAdvice(std::string_view argument) {
  static const std::pair<std::string_view, std::string_view> kRetired[] = {
      {"--zstd", "--zstd is the default now: drop it (--no-zstd writes raw chunks)"},
      {"--alpha-weighted",
       "--alpha-weighted is the default now: drop it (--no-alpha-weighted measures colour distances "
       "without the texels' alpha)"},
  };
  for (const auto& [flag, advice] : kRetired)
    if (argument == flag) return std::string(advice);
  return "";
}

CLI::Option* AddFlag(CLI::App& command, std::string_view flag, bool& value) {
  const OptionSpec& spec = RegisteredOption(flag);
  if (LongName(spec.flag).starts_with("--no-"))  // "--no-fit" turns fit.enabled off
    return command.add_flag_callback(
        spec.flag, [&value] { value = false; }, spec.help);
  return command.add_flag(spec.flag, value, spec.help);
}

CLI::Option* AddFlag(CLI::App& command, std::string_view flag, bool& value, const std::string& help) {
  const OptionSpec& spec = RegisteredOption(flag);
  if (!spec.worded_by_command) throw std::logic_error(spec.flag + " has the registry's help, not the command's");
  return command.add_flag(spec.flag, value, help);
}

}  // namespace voltree::app
