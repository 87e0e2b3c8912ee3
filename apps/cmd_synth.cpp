// voltree synth: photograph a procedural or imported tree in the studio -> a capture workspace
// with ground truth.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "core/files.h"
#include "core/progress.h"
#include "samples/studio.h"
#include "samples/tree_source.h"

namespace voltree::app {
namespace {

struct SynthArguments {
  TreeSource tree;
  StudioOptions studio;
  std::filesystem::path output;
  bool force = false;
  bool quiet = false;
};

void RunSynth(const SynthArguments& args) {
  StudioOptions studio = args.studio;
  studio.tree_name = TreeSourceName(args.tree);
  studio.Check();
  // Refuse an occupied output folder before the (possibly slow) tree is built.
  CheckCanReplaceFolder(args.output, args.force);
  Progress progress(args.quiet);
  std::vector<std::string> warnings;
  const TreeMesh mesh = LoadTreeMesh(args.tree, progress, &warnings);
  for (const std::string& warning : warnings) std::fprintf(stderr, "voltree: warning: %s\n", warning.c_str());
  PhotographTree(mesh, studio, args.output, progress, args.force);
}

}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "synth",
      "Photograph a synthetic tree in the photo studio: rings of cameras around a procedural or imported tree, "
      "in front of a place (realistic: a skyline of hills, tree lines and buildings, bushes, rocks and other trees "
      "on textured ground) or plain sky and ground. Writes a capture workspace: images/, mattes/, foreground/, "
      "sparse/ (true cameras), truth/ (held-out views, meta.json) and scene.json");
  auto args = std::make_shared<SynthArguments>();
  AddTreeSourceOptions(*command, args->tree, args->studio);
  AddStudioOptions(*command, args->studio);
  AddOption(*command, "--output", args->output, "Output workspace folder")->required();
  AddFlag(*command, "--force", args->force, "Replace the output folder if it exists and is not empty");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] { RunSynth(*args); });
}

}  // namespace voltree::app
