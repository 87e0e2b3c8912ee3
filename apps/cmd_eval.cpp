// voltree eval DIR: render the asset at the held-out truth cameras and at the input cameras,
// compare, and write DIR/report/{metrics.json,index.html,eval/}.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/eval_table.h"
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
      "view, with the asset's web page beside the truth, plots drawn by gnuplot when installed) and REPORT/eval/; prints a table and the page's path");
  struct Arguments {
    std::string dir, asset, report, levels = "all", codebook_sweep, scene_bench;
    EvaluateOptions options;
    bool no_input = false, no_images = false, no_plots = false, quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  EvaluateOptions& o = args->options;
  command->add_option("DIR", args->dir, "Capture workspace (sparse/, foreground/ or images/+mattes/, truth/, tree.vtree)")
      ->required();
  command->add_option("--asset", args->asset, "The asset to evaluate (default: DIR/tree.vtree)");
  command->add_option("--report", args->report,
                      "Report folder (default: DIR/report); its other files (contact sheet, orbit/) are kept");
  command->add_option("--grey", o.metrics.background_grey,
                      "Grey (0..255) that truth and render are composited over for the RGB metrics")
      ->capture_default_str();
  command->add_option("--levels", args->levels,
                      "all: the renderer's LOD (auto) and each octree level forced; auto: only the LOD")
      ->capture_default_str();
  command->add_flag("--no-input", args->no_input, "Skip the input views (default: compare them too)");
  command->add_flag("--no-images", args->no_images, "No side-by-side PNGs of the held-out views (default: written)");
  command->add_flag("--no-plots", args->no_plots, "Do not run gnuplot (default: plots when gnuplot is installed)");
  command->add_option("--codebook-sweep", args->codebook_sweep,
                      "JSON of PSNR per codebook size to plot (default: REPORT/codebook_sweep.json when it exists)");
  command->add_option("--scene-bench", args->scene_bench,
                      "JSON of ms per frame per number of trees to plot (default: REPORT/scene_bench.json when it "
                      "exists)");
  command->add_flag("--budget", o.budget,
                    "Also measure what each step costs (the volume, uncompressed billboards, VQ, DXT5, the LOD) at the "
                    "input and held-out views; needs DIR/volume; adds a table to the report and metrics.json");
  command->add_flag("--force", o.force,
                    "Replace REPORT/metrics.json, index.html or eval/ even when they were not written by eval "
                    "(default: only eval's own earlier report is replaced)");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    EvaluateOptions options = args->options;
    options.workspace = args->dir;
    options.asset = args->asset;
    options.report = args->report;
    options.codebook_sweep = args->codebook_sweep;
    options.scene_bench = args->scene_bench;
    options.each_level = EachLevelFromName(args->levels, "--levels");
    options.input_views = !args->no_input;
    options.images = !args->no_images;
    options.plots = !args->no_plots;
    Progress progress(args->quiet);
    const EvaluateResult result = EvaluateWorkspace(options, progress);
    PrintEvaluation(result);
    if (!result.budget.empty()) std::printf("\nerror budget\n%s", BudgetTable(result.budget).c_str());
  });
}

}  // namespace voltree::app
