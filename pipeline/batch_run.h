// `voltree batch ROOT`: every capture under ROOT through the stages, as jobs of the Snakemake
// workflow (workflows/Snakefile), which gives resume, partial reruns, parallel jobs and cluster
// profiles. This part only prepares the workflow's configuration, runs the real `snakemake` and
// reads back what the captures hold.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/progress.h"
#include "pipeline/batch_summary.h"

namespace voltree {

struct BatchOptions {
  std::filesystem::path root;       // folders ROOT/TREE/images/
  int jobs = 1;                     // jobs at once; locally the cores are split between them
  bool jobs_given = false;          // with a profile, -j overrides the profile's own `jobs` only when given
  std::string profile;              // a Snakemake profile (folder or name); empty: run on this machine
  bool dry_run = false;             // print the planned jobs, run nothing
  std::filesystem::path voltree;    // the binary the workflow's jobs run
  std::filesystem::path snakefile;  // workflows/Snakefile
  std::string search_path;          // where to look for `snakemake` ($PATH)
  std::string home;                 // $HOME: profiles in ~/.config/snakemake/
  int cores = 0;                    // this machine's cores (0: as the system says)
  void Check() const;
};

struct BatchResult {
  std::vector<CaptureSummary> rows;  // captures, then skipped folders
  std::filesystem::path snakemake_log;
  std::string jobs;  // snakemake's table of the jobs it planned, or "Nothing to be done."
  int captures = 0;
  std::filesystem::path scene;      // ROOT/scene.json when the batch wrote it
  std::filesystem::path scene_log;  // the scene rule's log when it failed (a bad survey CSV)
  int failed = 0;
};

// Where Snakemake 7 looks for a profile named `profile`: the folder itself, then
// ~/.config/snakemake/NAME and /etc/xdg/snakemake/NAME; each must hold config.yaml. Throws Error
// naming the places looked at.
std::filesystem::path FindSnakemakeProfile(const std::string& profile, const std::string& home);

// The snakemake command line for `options` (after the program name).
std::vector<std::string> SnakemakeArguments(const BatchOptions& options, const std::filesystem::path& profile);

BatchResult RunBatch(const BatchOptions& options, Progress& progress);

}  // namespace voltree
