// voltree run DIR: matte, calibrate (each only when missing), reconstruct, compress, orbit renders
// and evaluation on a user's capture workspace.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "apps/eval_table.h"
#include "core/progress.h"
#include "pipeline/run_workspace.h"

namespace voltree::app {

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
    std::string levels = "7";
    std::string dir, refine = "infoflow", camera_model = "SIMPLE_RADIAL", matcher = "exhaustive", eval_levels = "all";
    RunOptions options;
    bool no_fit = false, quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  RunOptions& o = args->options;
  command->add_option("DIR", args->dir, "Capture workspace with images/ (and optionally mattes/, sparse/, truth/)")
      ->required();
  command->add_option("--refine", args->refine, "Matting when mattes/ is missing: infoflow, guided or none")
      ->capture_default_str();
  command->add_option("--camera-model", args->camera_model,
                      "COLMAP camera model when sparse/ is missing: SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, "
                      "OPENCV")
      ->capture_default_str();
  command->add_option("--max-image-size", o.calibrate.max_image_size,
                      "COLMAP feature extraction: longest side in pixels")
      ->capture_default_str();
  command->add_option("--matcher", args->matcher, "COLMAP matcher: exhaustive, or sequential for photos in a walk")
      ->capture_default_str();
  command->add_option("--levels", args->levels,
                      "Hierarchy levels: level 0 is the root, the finest has branching^(levels-1) cells per axis; auto: as many as the photos fill (a finest texel covers about one photo pixel)")
      ->capture_default_str();
  command->add_flag("--no-fit", args->no_fit,
                    "Keep the tomography's billboards: do not fit them to the photos (faster; to compare)");
  command->add_option("--codebook", o.compress.colour_codebook, "Colour codebook size")->capture_default_str();
  command->add_option("--alpha-codebook", o.compress.alpha_codebook, "Alpha codebook size")->capture_default_str();
  command->add_option("--orbit", o.orbit.frames, "Orbit frames rendered into DIR/report/orbit/")->capture_default_str();
  command->add_option("--orbit-size", o.orbit.size, "Orbit frame side in pixels (square)")->capture_default_str();
  command->add_option("--eval-levels", args->eval_levels,
                      "all: evaluate the renderer's LOD and each octree level forced; auto: only the LOD (faster on "
                      "large photos)")
      ->capture_default_str();
  command->add_flag("--force", o.force,
                    "Replace volume/, tree.vtree, report/orbit/ and report files not written by eval (default: "
                    "refuse); existing mattes/ and sparse/ are always kept");
  command->add_flag("--no-guards", [args](std::int64_t) { args->options.guards = false; },
                    "Skip the guards that stop a run, writing no asset, when mattes cover most of a photo or almost "
                    "nothing, disagree with each other through the cameras, or are not reproduced by the "
                    "reconstruction (to inspect what such input gives)");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    RunOptions options = args->options;
    options.workspace = args->dir;
    options.reconstruct.fit.enabled = !args->no_fit;
    options.reconstruct.levels = ParseLevels("--levels", args->levels);
    options.reconstruct.auto_levels = options.reconstruct.levels == 0;
    if (options.reconstruct.auto_levels) options.reconstruct.levels = 7;  // replaced once the photos are read
    options.matte.matte.refine = ParseRefineMethod(args->refine);
    options.calibrate.camera_model = args->camera_model;
    options.calibrate.matcher = args->matcher;
    options.evaluate.each_level = EachLevelFromName(args->eval_levels, "--eval-levels");
    Progress progress(args->quiet);
    const RunResult result = RunWorkspace(options, progress);
    std::printf("%-12s %9s\n", "stage", "seconds");
    for (const StageTime& stage : result.stages) {
      if (stage.what == "ran") std::printf("%-12s %9.1f\n", stage.stage.c_str(), stage.seconds);
      else std::printf("%-12s %9s  (%s)\n", stage.stage.c_str(), "-", stage.what.c_str());
    }
    PrintEvaluation(result.evaluation);
  });
}

}  // namespace voltree::app
