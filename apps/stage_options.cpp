#include "apps/stage_options.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "apps/option_parsing.h"
#include "apps/option_registry.h"

namespace voltree::app {
namespace {

const std::vector<std::pair<std::string, CameraModel>> kCameraModels = {{"SIMPLE_PINHOLE", CameraModel::kSimplePinhole},
                                                                        {"PINHOLE", CameraModel::kPinhole},
                                                                        {"SIMPLE_RADIAL", CameraModel::kSimpleRadial},
                                                                        {"RADIAL", CameraModel::kRadial},
                                                                        {"OPENCV", CameraModel::kOpenCV}};

}  // namespace

void AddTreeSourceOptions(CLI::App& command, TreeSource& tree, StudioOptions& studio) {
  AddOption(command, "--tree", tree.tree);
  AddParsedOption<uint64_t>(
      command, "--seed", tree.seed,
      [&studio](const std::string& text, uint64_t& seed) {
        seed = ParseCount("--seed", text);
        studio.seed = seed;  // one seed for the tree and its surroundings
      },
      std::to_string(tree.seed));
  AddChoice(command, "--mesh-up", tree.up, {{"y", UpAxis::kY}, {"z", UpAxis::kZ}});
}

void AddStudioOptions(CLI::App& command, StudioOptions& studio) {
  AddOption(command, "--views", studio.views);
  AddOption(command, "--held-out", studio.held_out);
  AddOption(command, "--rings", studio.rings);
  AddParsedOption<StudioOptions>(
      command, "--size", studio,
      [](const std::string& text, StudioOptions& out) { std::tie(out.width, out.height) = ParseSize("--size", text); },
      Str(studio.width, "x", studio.height));
  AddOption(command, "--supersample", studio.supersample);
  AddChoice(command, "--camera", studio.camera_model, kCameraModels);
  AddParsedOption<std::vector<double>>(
      command, "--distortion", studio.distortion,
      [](const std::string& text, std::vector<double>& out) { out = ParseNumbers("--distortion", text); }, "");
  AddOption(command, "--fov", studio.fov_degrees);
  AddOption(command, "--min-elevation", studio.min_elevation_degrees);
  AddChoice(command, "--backdrop", studio.backdrop,
            {{"realistic", BackdropStyle::kRealistic}, {"plain", BackdropStyle::kPlain}});
}

void AddCalibrateOptions(CLI::App& command, CalibrateOptions& calibrate) {
  AddOption(command, "--camera-model", calibrate.camera_model);
  AddOption(command, "--camera-params", calibrate.camera_params)->delimiter(',');
  AddOption(command, "--max-image-size", calibrate.max_image_size);
  AddOption(command, "--max-features", calibrate.max_features);
  AddOption(command, "--matcher", calibrate.matcher);
  AddOption(command, "--min-registered", calibrate.min_registered);
  AddOption(command, "--robust-loss", calibrate.adjust.loss_scale);
  AddChoice(command, "--mask", calibrate.mask,
            {{"all", FeatureMask::kAll}, {"tree", FeatureMask::kTree}, {"near", FeatureMask::kNear}});
  AddParsedOption<std::optional<Eigen::Vector3d>>(
      command, "--up", calibrate.up,
      [](const std::string& text, std::optional<Eigen::Vector3d>& up) {
        const std::vector<double> xyz = ParseNumbers("--up", text);
        if (xyz.size() != 3) Fail("--up '", text, "': expected a direction x,y,z");
        up = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
      },
      "");
  AddParsedOption<std::optional<double>>(
      command, "--height", calibrate.height_metres,
      [](const std::string& text, std::optional<double>& height) {
        const std::vector<double> metres = ParseNumbers("--height", text);
        if (metres.size() != 1) Fail("--height '", text, "': expected one number of metres");
        height = metres[0];
      },
      "");
  AddOption(command, "--import", calibrate.import_model)->check(CLI::ExistingDirectory);
  AddOption(command, "--known-cameras", calibrate.known_cameras)->check(CLI::ExistingDirectory);
  AddOption(command, "--hull-resolution", calibrate.hull.resolution);
  AddFlag(command, "--no-affine", calibrate.affine_features);
  AddFlag(command, "--no-guided", calibrate.guided_matching);
}

void AddMatteOptions(CLI::App& command, MatteOptions& matte) {
  AddChoice(command, "--refine", matte.refine,
            {{"infoflow", RefineMethod::kInfoFlow}, {"guided", RefineMethod::kGuided}, {"none", RefineMethod::kNone}});
  AddOption(command, "--horizon", matte.horizon);
  AddOption(command, "--band", matte.band_radius);
}

void AddReconstructOptions(CLI::App& command, ReconstructOptions& reconstruct) {
  AddParsedOption<ReconstructOptions>(
      command, "--levels", reconstruct,
      [](const std::string& text, ReconstructOptions& out) {
        out.auto_levels = text == "auto";  // the count is chosen once the photos are read
        if (!out.auto_levels) out.levels = ParseLevels("--levels", text);
      },
      reconstruct.auto_levels ? "auto" : std::to_string(reconstruct.levels));
  AddOption(command, "--branching", reconstruct.branching);
  AddOption(command, "--texels", reconstruct.texels);
  AddOption(command, "--margin", reconstruct.margin);
  AddOption(command, "--carve-alpha", reconstruct.carve_alpha);
  OpacityOptions& opacity = reconstruct.opacity;
  AddOption(command, "--carve-views", opacity.carve_views);
  AddChoice(command, "--solver", opacity.solver, {{"sart", SolverKind::kSart}, {"ceres", SolverKind::kCeres}});
  AddOption(command, "--iterations", opacity.sart.iterations);
  AddOption(command, "--relaxation", opacity.sart.relaxation);
  AddOption(command, "--ceres-iterations", opacity.ceres.iterations);
  AddOption(command, "--huber", opacity.ceres.huber);
  AddOption(command, "--refine-depth", opacity.refine_min_optical_depth);
  AddOption(command, "--prune", reconstruct.billboards.prune);
  AddOption(command, "--billboard-scale", reconstruct.billboards.scale);
  AddFlag(command, "--no-fit", reconstruct.fit.enabled);
  AddOption(command, "--fit-iterations", reconstruct.fit.iterations);
  AddOption(command, "--fit-prior", reconstruct.fit.prior);
  AddOption(command, "--fit-neighbours", reconstruct.fit.neighbours);
  AddOption(command, "--fit-neighbour-weight", reconstruct.fit.neighbour_weight);
}

void DeepenWithinBudgetUnlessLevelsGiven(const CLI::App& command, uint64_t max_bytes, ReconstructOptions& reconstruct) {
  if (command.get_option("--levels")->count() == 0) reconstruct.deepen_within_bytes = max_bytes;
}

void AddCompressOptions(CLI::App& command, CompressOptions& compress) {
  AddOption(command, "--codebook", compress.colour_codebook);
  AddOption(command, "--alpha-codebook", compress.alpha_codebook);
  AddChoice(command, "--space", compress.space, {{"lab", ColourSpace::kLab}, {"rgb", ColourSpace::kRgb}});
  const std::vector<std::pair<std::string, CodewordRule>> rules{{"classic", CodewordRule::kCentroid},
                                                                {"modified", CodewordRule::kClosestMember}};
  AddChoice(command, "--gla", compress.colour_rule, rules);
  AddChoice(command, "--alpha-gla", compress.alpha_rule, rules);
  AddFlag(command, "--no-alpha-weighted", compress.alpha_weighted);
  AddFlag(command, "--no-codebook-trade", compress.trade_codebooks);
  AddOption(command, "--gla-tolerance", compress.tolerance);
  AddOption(command, "--gla-iterations", compress.max_iterations);
  AddOption(command, "--gla-seed", compress.seed);
  AddParsedOption<uint64_t>(
      command, "--max-bytes", compress.max_bytes,
      [](const std::string& text, uint64_t& bytes) { bytes = ParseBytes("--max-bytes", text); },
      compress.max_bytes % (1 << 20) == 0 ? Str(compress.max_bytes >> 20, "MiB") : Str(compress.max_bytes));
  AddFlag(command, "--no-zstd", compress.zstd);
}

void WarnAboutCompression(const CLI::App& command, const CompressWorkspaceResult& compressed, uint64_t max_bytes,
                          bool quiet) {
  // The default size is only the largest one tried, so a small volume falling short of it is no news.
  const auto warn_if_smaller = [&command](const char* option, int asked, size_t made) {
    if (command.get_option(option)->count() > 0 && made < size_t(asked))
      std::fprintf(stderr,
                   "voltree: warning: %s %d: the codebook has only %zu codewords; the volume's billboards give no "
                   "more distinct ones\n",
                   option, asked, made);
  };
  warn_if_smaller("--codebook", compressed.kept.colour_codebook, compressed.stats.colour.codebook.size());
  warn_if_smaller("--alpha-codebook", compressed.kept.alpha_codebook, compressed.stats.alpha.codebook.size());
  if (!compressed.within_budget && quiet)
    std::fprintf(stderr,
                 "voltree: warning: %s is %llu bytes, over --max-bytes %llu even with codebooks %d / %d; "
                 "reconstruct with fewer --levels or a lower --prune for a smaller asset\n",
                 compressed.asset.string().c_str(), static_cast<unsigned long long>(compressed.bytes),
                 static_cast<unsigned long long>(max_bytes), compressed.kept.colour_codebook,
                 compressed.kept.alpha_codebook);
}

void AddOrbitOptions(CLI::App& command, OrbitFramesOptions& orbit) {
  AddOption(command, "--orbit", orbit.frames);
  AddOption(command, "--orbit-size", orbit.size);
}

void AddEvaluateOptions(CLI::App& command, EvaluateOptions& evaluate) {
  AddOption(command, "--grey", evaluate.metrics.background_grey);
  AddChoice(command, "--eval-levels", evaluate.each_level, {{"all", true}, {"auto", false}});
  AddOption(command, "--distance", evaluate.distance);
  AddFlag(command, "--no-input", evaluate.input_views);
  AddFlag(command, "--no-images", evaluate.images);
  AddFlag(command, "--no-plots", evaluate.plots);
  AddFlag(command, "--budget", evaluate.budget);
}

void AddRenderOptions(CLI::App& command, TreeRenderOptions& render) {
  AddOption(command, "--level", render.lod.forced_level);
  AddOption(command, "--texel-pixels", render.lod.max_texel_pixels);
  AddFlag(command, "--tint-levels", render.tint_levels);
  AddFlag(command, "--no-trim", render.trim_quads);
  AddBackgroundOption(command, render.background);
  AddOption(command, "--billboard-scale", render.billboard_scale);
}

CLI::Option* AddBackgroundOption(CLI::App& command, std::array<float, 4>& background) {
  const auto component = [&](int c) { return std::to_string(int(std::lround(background[c] * 255))); };
  const std::string shown = background[3] == 0 ? "transparent" : component(0) + "," + component(1) + "," + component(2);
  return AddParsedOption<std::array<float, 4>>(
      command, "--background", background,
      [](const std::string& text, std::array<float, 4>& out) { out = ParseBackground("--background", text); }, shown);
}

void AddThreadsOption(CLI::App& command, int& threads) { AddOption(command, "--threads", threads); }

}  // namespace voltree::app
