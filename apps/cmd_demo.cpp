// voltree demo: the whole pipeline on a built-in synthetic tree, in one command.
#include <memory>
#include <optional>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "core/error.h"
#include "pipeline/demo.h"

namespace voltree::app {

void AddDemoCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "demo",
      "Run the whole pipeline on a built-in synthetic tree: photograph it in the studio (true cameras and "
      "mattes), reconstruct its opacity and billboard textures, compress them into an asset. Writes a "
      "workspace (default out/demo/) with report/contact_sheet.png, tree.vtree and demo.json (timings, sizes)");
  struct Arguments {
    DemoOptions options;
    std::string output = "out/demo", size = "512x512", up = "y";
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  DemoOptions& o = args->options;
  command->add_option("-o,--output", args->output, "Output folder; a previous demo's folder is replaced")
      ->capture_default_str();
  command->add_option("--tree", o.tree.tree, "A preset (oak, pine, young-oak) or a mesh file (.gltf, .glb, .obj)")
      ->capture_default_str();
  command->add_option("--seed", o.tree.seed, "Seed of the procedural tree")->capture_default_str();
  command->add_option("--up", args->up, "Up axis of a mesh file: y or z")->capture_default_str();
  command->add_option("--views", o.studio.views, "Input photos")->capture_default_str();
  command->add_option("--held-out", o.studio.held_out, "Held-out truth views")->capture_default_str();
  command->add_option("--size", args->size, "Photo size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--levels", o.reconstruct.levels, "Octree levels (level L has 2^L cells per axis)")
      ->capture_default_str();
  command->add_option("--codebook", o.compress.colour_codebook, "Colour codebook size")->capture_default_str();
  command->add_option("--alpha-codebook", o.compress.alpha_codebook, "Alpha codebook size")->capture_default_str();
  command->add_flag("--force", o.force, "Replace an output folder that is not a previous demo's");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    DemoOptions options = args->options;
    options.output = args->output;
    std::tie(options.studio.width, options.studio.height) = ParseSize("--size", args->size);
    const std::optional<UpAxis> up = UpAxisFromName(args->up);
    if (!up) Fail("--up '", args->up, "': expected y or z");
    options.tree.up = *up;
    Progress progress(args->quiet);
    const std::filesystem::path summary = RunDemo(options, progress);
    std::printf("%s\n", summary.string().c_str());
  });
}

}  // namespace voltree::app
