// voltree demo: the whole pipeline on a built-in synthetic tree, in one command.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "apps/commands.h"
#include "apps/eval_table.h"
#include "apps/option_parsing.h"
#include "core/error.h"
#include "pipeline/demo.h"

namespace voltree::app {

void AddDemoCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "demo",
      "Run the whole pipeline on a built-in synthetic tree: photograph it in the studio (true cameras and "
      "mattes), reconstruct its opacity and billboard textures, compress them into an asset, render an orbit and "
      "evaluate the asset against the studio's held-out views. Writes a workspace (default out/demo/) with "
      "tree.vtree, report/index.html (metrics, side-by-side images, plots), report/orbit/, "
      "report/contact_sheet.png and demo.json (timings per stage, sizes, headline metrics); prints the metrics "
      "table and the path of report/index.html");
  struct Arguments {
    std::string levels = "7";
    DemoOptions options;
    std::string output = "out/demo", size = "512x512", up = "y";
    bool no_eval = false, no_fit = false, quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  DemoOptions& o = args->options;
  command->add_option("-o,--output", args->output, "Output folder; the files a previous demo wrote there are replaced, any others kept")
      ->capture_default_str();
  command->add_option("--tree", o.tree.tree, "A preset (oak, pine, young-oak) or a mesh file (.gltf, .glb, .obj)")
      ->capture_default_str();
  command->add_option("--seed", o.tree.seed, "Seed of the procedural tree")->capture_default_str();
  command->add_option("--up", args->up, "Up axis of a mesh file: y or z")->capture_default_str();
  command->add_option("--views", o.studio.views, "Input photos")->capture_default_str();
  command->add_option("--held-out", o.studio.held_out, "Held-out truth views")->capture_default_str();
  command->add_option("--size", args->size, "Photo size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--levels", args->levels,
                      "Hierarchy levels: level 0 is the root, the finest has branching^(levels-1) cells per axis; auto: as many as the photos fill (a finest texel covers about one photo pixel)")
      ->capture_default_str();
  command->add_option("--codebook", o.compress.colour_codebook, "Colour codebook size")->capture_default_str();
  command->add_option("--alpha-codebook", o.compress.alpha_codebook, "Alpha codebook size")->capture_default_str();
  command->add_option("--orbit", o.orbit.frames, "Orbit frames rendered into report/orbit/ (0: none)")
      ->capture_default_str();
  command->add_option("--orbit-size", o.orbit.size, "Orbit frame side in pixels (square)")->capture_default_str();
  command->add_flag("--no-fit", args->no_fit,
                    "Keep the tomography's billboards: do not fit them to the photos (faster; to compare)");
  command->add_flag("--no-eval", args->no_eval, "Skip the evaluation report (default: evaluate)");
  command->add_flag("--colmap", o.colmap,
                    "Calibrate the photos with COLMAP (SIFT on the CPU, about a minute) instead of using the studio's "
                    "true cameras; the true input cameras are kept in truth/input_sparse/ and the held-out cameras "
                    "are moved into COLMAP's frame by the similarity fitted between the two, so the evaluation "
                    "includes calibration error; the lower camera ring is raised to 20 degrees, as COLMAP registers "
                    "grazing views of the ground poorly (default: true cameras)");
  command->add_flag("--force", o.force, "Write into a non-empty folder that is not a previous demo's, beside its files (never replacing one)");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    DemoOptions options = args->options;
    options.output = args->output;
    std::tie(options.studio.width, options.studio.height) = ParseSize("--size", args->size);
    const std::optional<UpAxis> up = UpAxisFromName(args->up);
    if (!up) Fail("--up '", args->up, "': expected y or z");
    options.tree.up = *up;
    options.evaluate = !args->no_eval;
    options.reconstruct.fit.enabled = !args->no_fit;
    options.reconstruct.levels = ParseLevels("--levels", args->levels);
    options.reconstruct.auto_levels = options.reconstruct.levels == 0;
    if (options.reconstruct.auto_levels) options.reconstruct.levels = 7;  // replaced once the photos are read
    // At 5 degrees half of the photos fail to register (bench/calibrate.cpp); 20 registers all.
    if (options.colmap) options.studio.min_elevation_degrees = std::max(options.studio.min_elevation_degrees, 20.0);
    Progress progress(args->quiet);
    const DemoResult result = RunDemo(options, progress);
    std::printf("%s (%.1f s)\n", result.summary.string().c_str(), result.seconds);
    if (!result.index_html.empty()) {
      std::printf("%s", EvaluationTable(result.evaluation).c_str());
      std::printf("%s\n", result.index_html.string().c_str());
    }
  });
}

}  // namespace voltree::app
