// voltree eval DIR: render the asset at the held-out truth cameras and at the input cameras,
// compare, and write DIR/report/{metrics.json,index.html,eval/}.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/eval_table.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "core/progress.h"
#include "pipeline/evaluate.h"

namespace voltree::app {

void AddEvalCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "eval",
      "Evaluate an asset against the truth: render it at the held-out cameras (DIR/truth/sparse, compared with "
      "DIR/truth/rgba/) and at the input cameras (DIR/sparse, compared with DIR/foreground/ or the photos and "
      "mattes: self-consistency), with the renderer's own LOD and with each octree level forced. Metrics: RGB "
      "PSNR and SSIM over a fixed grey background, alpha PSNR, precision and recall of covered pixels, "
      "multi-scale RMS. Writes REPORT/metrics.json, REPORT/index.html (truth | voltree | difference per held-out "
      "view, with the asset's web page beside the truth, plots drawn by gnuplot when installed) and REPORT/eval/; "
      "prints a table and the page's path");
  struct Arguments {
    std::filesystem::path dir;
    EvaluateOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  EvaluateOptions& o = args->options;
  command
      ->add_option("DIR", args->dir, "Capture workspace (sparse/, foreground/ or images/+mattes/, truth/, tree.vtree)")
      ->required();
  AddOption(*command, "--asset", o.asset);
  AddOption(*command, "--report", o.report);
  AddEvaluateOptions(*command, o);
  AddOption(*command, "--codebook-sweep", o.codebook_sweep);
  AddOption(*command, "--scene-bench", o.scene_bench);
  AddFlag(*command, "--force", o.force,
          "Replace REPORT/metrics.json, index.html or eval/ even when they were not written by eval (default: only "
          "eval's own earlier report is replaced)");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] {
    Progress progress(args->quiet);
    const EvaluateResult result = EvaluateWorkspace(args->dir, args->options, progress);
    PrintEvaluation(result);
    if (!result.budget.empty()) std::printf("\nerror budget\n%s", BudgetTable(result.budget).c_str());
  });
}

}  // namespace voltree::app
