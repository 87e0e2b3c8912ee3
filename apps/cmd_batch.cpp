// voltree batch ROOT: every capture ROOT/TREE/images/ through the stages as jobs of the Snakemake
// workflow (workflows/Snakefile), then a summary table of the captures.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "core/error.h"
#include "core/progress.h"
#include "pipeline/batch_run.h"

namespace voltree::app {
namespace {

std::string Environment(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? "" : value;
}

}  // namespace

void AddBatchCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "batch",
      "Many trees: every capture folder ROOT/TREE/ holding images/ through matte, calibrate (each only when "
      "missing), reconstruct, compress and eval (when TREE/truth/ exists), as jobs of the Snakemake workflow "
      "workflows/Snakefile, then ROOT/scene.json with every asset (on a grid, or at the positions of a survey "
      "CSV named in ROOT/batch.yaml). Run again, it resumes: only missing or outdated outputs are built. One "
      "failed capture does not stop the others; the summary names its log. Stage options, threads and memory "
      "per job: ROOT/batch.yaml (keys of workflows/config.yaml). Needs snakemake (docs/batch.md)");
  struct Arguments {
    std::string root;
    BatchOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  BatchOptions& o = args->options;
  command->add_option("ROOT", args->root, "Folder of capture workspaces, one per tree: ROOT/TREE/images/")->required();
  auto* jobs = AddOption(*command, "--jobs", o.jobs);
  AddOption(*command, "--profile", o.profile);
  AddFlag(*command, "--dry-run", o.dry_run);
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args, jobs] {
    BatchOptions options = args->options;
    options.jobs_given = jobs->count() > 0;
    options.root = args->root;
    options.voltree = std::filesystem::read_symlink("/proc/self/exe");
    options.snakefile = std::filesystem::path(VOLTREE_WORKFLOWS_DIR) / "Snakefile";
    options.search_path = Environment("PATH");
    options.home = Environment("HOME");
    Progress progress(args->quiet);
    const BatchResult result = RunBatch(options, progress);
    std::printf("%s%s\n", options.dry_run ? "planned " : "", result.jobs.c_str());
    std::printf("%s", FormatBatchSummary(result.rows).c_str());
    if (!result.scene.empty())
      std::printf("scene: %s (%d trees)\n", result.scene.string().c_str(), result.captures);
    else if (!result.scene_log.empty())
      std::printf("scene: failed; log: %s\n", result.scene_log.string().c_str());
    else if (!options.dry_run)
      std::printf("scene: not written (it needs every capture's asset)\n");
    std::printf("snakemake log: %s\n", result.snakemake_log.string().c_str());
    std::fflush(stdout);  // the table before the error line
    if (result.failed > 0)
      Fail(result.failed, " of ", result.captures,
           " captures failed; their logs are named above. Run the same "
           "command again after fixing them: what was built is kept");
    if (!result.scene_log.empty())
      Fail("the scene of the batch failed (", result.scene_log.string(), "); every asset was built");
  });
}

}  // namespace voltree::app
