// voltree demo: the whole pipeline on a built-in synthetic tree, in one command.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/eval_table.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
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
    DemoOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  DemoOptions& o = args->options;
  AddOption(*command, "--output", o.output,
            "Output folder; the files a previous demo wrote there are replaced, any others kept")
      ->capture_default_str();
  AddTreeSourceOptions(*command, o.tree, o.studio);
  AddStudioOptions(*command, o.studio);
  AddReconstructOptions(*command, o.reconstruct);
  AddCompressOptions(*command, o.compress);
  AddOrbitOptions(*command, o.orbit);
  AddEvaluateOptions(*command, o.evaluation);
  AddFlag(*command, "--no-eval", o.evaluate);
  AddFlag(*command, "--colmap", o.colmap);
  AddThreadsOption(*command, o.reconstruct.threads);
  AddFlag(*command, "--force", o.force,
          "Write into a non-empty folder that is not a previous demo's, beside its files (never replacing one)");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([command, args] {
    DemoOptions options = args->options;
    DeepenWithinBudgetUnlessLevelsGiven(*command, options.compress.max_bytes, options.reconstruct);
    // At 5 degrees half of the photos fail to register (bench/calibrate.cpp); 20 registers all.
    if (options.colmap) options.studio.min_elevation_degrees = std::max(options.studio.min_elevation_degrees, 20.0);
    Progress progress(args->quiet);
    const DemoResult result = RunDemo(options, progress);
    WarnAboutCompression(*command, result.compressed, options.compress.max_bytes, args->quiet);
    std::printf("%s (%.1f s)\n", result.summary.string().c_str(), result.seconds);
    if (!result.index_html.empty()) {
      std::printf("%s", EvaluationTable(result.evaluation).c_str());
      std::printf("%s\n", result.index_html.string().c_str());
    }
  });
}

}  // namespace voltree::app
