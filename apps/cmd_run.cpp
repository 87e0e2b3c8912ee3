// voltree run DIR: matte, calibrate (each only when missing), reconstruct, compress, orbit renders
// and evaluation on a user's capture workspace.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/eval_table.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "core/progress.h"
#include "pipeline/run_workspace.h"

namespace voltree::app {
namespace {

void PrintStageTimes(const RunResult& result) {
  std::printf("%-12s %9s\n", "stage", "seconds");
  for (const StageTime& stage : result.stages) {
    if (stage.what == "ran")
      std::printf("%-12s %9.1f\n", stage.stage.c_str(), stage.seconds);
    else
      std::printf("%-12s %9s  (%s)\n", stage.stage.c_str(), "-", stage.what.c_str());
  }
}

}  // namespace

void AddRunCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "run",
      "The whole pipeline on a capture workspace DIR holding images/ (your photos of one tree) and optionally "
      "mattes/ and sparse/: calibrate with COLMAP (only when sparse/ is missing), matte (only when mattes/ is "
      "missing; with photos alone after calibrating, and the mattes that disagree through the cameras are matted "
      "again inside the visual hull of the others), check the mattes (coverage, visual hull), reconstruct "
      "(DIR/volume/), compress (DIR/tree.vtree), orbit renders (DIR/report/orbit/) and "
      "eval (DIR/report/index.html: held-out views when DIR/truth/ exists, else the input views only, which "
      "measures self-consistency). Stops without writing an asset when a guard fails (a matte covering most of "
      "its photo or almost nothing, mattes that disagree with the cameras, a reconstruction that does not "
      "reproduce its mattes). Prints each stage's time and the evaluation table");
  struct Arguments {
    RunOptions options;
    int threads = 0;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  RunOptions& o = args->options;
  command->add_option("DIR", o.workspace, "Capture workspace with images/ (and optionally mattes/, sparse/, truth/)")
      ->required();
  AddCalibrateOptions(*command, o.calibrate);
  AddMatteOptions(*command, o.matte.matte);
  AddReconstructOptions(*command, o.reconstruct);
  AddCompressOptions(*command, o.compress);
  AddOrbitOptions(*command, o.orbit);
  AddEvaluateOptions(*command, o.evaluate);
  AddFlag(*command, "--no-guards", o.guards);
  AddThreadsOption(*command, args->threads);
  AddFlag(*command, "--force", o.force,
          "Replace volume/, tree.vtree, report/orbit/ and report files not written by eval (default: refuse); "
          "existing mattes/ and sparse/ are always kept");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([command, args] {
    RunOptions options = args->options;
    options.matte.threads = options.reconstruct.threads = args->threads;
    DeepenWithinBudgetUnlessLevelsGiven(*command, options.compress.max_bytes, options.reconstruct);
    Progress progress(args->quiet);
    const RunResult result = RunWorkspace(options, progress);
    if (result.compressed) WarnAboutCompression(*command, *result.compressed, options.compress.max_bytes, args->quiet);
    PrintStageTimes(result);
    PrintEvaluation(result.evaluation);
  });
}

}  // namespace voltree::app
