// voltree synth: photograph a procedural or imported tree in the studio -> a capture workspace
// with ground truth.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "core/error.h"
#include "core/files.h"
#include "core/progress.h"
#include "samples/studio.h"
#include "samples/tree_source.h"

namespace voltree::app {
namespace {

struct SynthArguments {
  std::string tree = "oak";
  int views = 24;
  int held_out = 8;
  int rings = 2;
  std::string size = "512x512";
  int supersample = 4;
  uint64_t seed = 1;
  std::string up = "y";
  std::string camera = "PINHOLE";
  std::string distortion;
  double fov = 40;
  double min_elevation = 5;  // lowest ring (degrees)
  std::string backdrop = "realistic";
  std::string output;
  bool force = false;
  bool quiet = false;
};

void RunSynth(const SynthArguments& args) {
  StudioOptions options;
  options.views = args.views;
  options.held_out = args.held_out;
  options.rings = args.rings;
  std::tie(options.width, options.height) = ParseSize("--size", args.size);
  options.supersample = args.supersample;
  options.seed = args.seed;
  options.camera_model = CameraModelFromName(args.camera);
  if (!args.distortion.empty()) options.distortion = ParseNumbers("--distortion", args.distortion);
  options.fov_degrees = args.fov;
  options.min_elevation_degrees = args.min_elevation;
  options.backdrop = BackdropStyleFromName(args.backdrop);
  TreeSource source;
  source.tree = args.tree;
  source.seed = args.seed;
  const std::optional<UpAxis> up = UpAxisFromName(args.up);
  if (!up) Fail("--up '", args.up, "': expected y or z");
  source.up = *up;
  options.tree_name = TreeSourceName(source);
  options.Check();
  // Refuse an occupied output folder before the (possibly slow) tree is built.
  const std::filesystem::path output(args.output);
  CheckCanReplaceFolder(output, args.force);

  Progress progress(args.quiet);
  std::vector<std::string> warnings;
  const TreeMesh mesh = LoadTreeMesh(source, progress, &warnings);
  for (const std::string& warning : warnings) std::fprintf(stderr, "voltree: warning: %s\n", warning.c_str());
  PhotographTree(mesh, options, output, progress, args.force);
}

}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "synth",
      "Photograph a synthetic tree in the photo studio: rings of cameras around a procedural or imported tree, "
      "in front of a place (realistic: a skyline of hills, tree lines and buildings, bushes, rocks and other trees "
      "on textured ground) or plain sky and ground. Writes a capture workspace: images/, mattes/, foreground/, sparse/ (true "
      "cameras), truth/ (held-out views, meta.json) and scene.json");
  auto args = std::make_shared<SynthArguments>();
  command->add_option("--tree", args->tree,
                      "A preset (oak, pine, young-oak) or a mesh file (.gltf, .glb, .obj)")
      ->capture_default_str();
  command->add_option("--views", args->views, "Number of input photos, spread over the rings")
      ->capture_default_str();
  command->add_option("--held-out", args->held_out, "Number of held-out truth views between the rings")
      ->capture_default_str();
  command->add_option("--rings", args->rings, "Camera rings at different elevations (5 to 35 degrees)")
      ->capture_default_str();
  command->add_option("--size", args->size, "Photo size WIDTHxHEIGHT in pixels")->capture_default_str();
  command->add_option("--supersample", args->supersample,
                      "Samples per pixel and axis (mattes get 1/S^2 alpha steps)")
      ->capture_default_str();
  command->add_option("--seed", args->seed, "Seed of the procedural tree, ground, sky and ring rotation")
      ->capture_default_str();
  command->add_option("--up", args->up, "Up axis of a mesh FILE: y (glTF convention) or z")->capture_default_str();
  command->add_option("--camera", args->camera,
                      "Camera model: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL or OPENCV")
      ->capture_default_str();
  command->add_option("--distortion", args->distortion,
                      "Comma-separated distortion parameters of the model (SIMPLE_RADIAL: k; RADIAL: k1,k2; "
                      "OPENCV: k1,k2,p1,p2); default none");
  command->add_option("--fov", args->fov, "Field of view across the smaller image side, degrees")
      ->capture_default_str();
  command->add_option("--min-elevation", args->min_elevation,
                      "Elevation of the lowest ring in degrees, seen from the middle of the tree's bounds (the highest is 35); "
                      "5 looks almost level at the tree, as a person holding the camera would")
      ->capture_default_str();
  command->add_option("--backdrop", args->backdrop,
                      "What stands behind the tree: realistic (a place: skyline, bushes, rocks, other trees) or "
                      "plain (sky and textured ground only). Mattes and truth are the tree's alone either way")
      ->capture_default_str();
  command->add_option("-o,--output", args->output, "Output workspace folder")->required();
  command->add_flag("--force", args->force, "Replace the output folder if it exists and is not empty");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] { RunSynth(*args); });
}

}  // namespace voltree::app
