#include "pipeline/batch_run.h"

#include <unistd.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "capture/colmap_runner.h"
#include "core/error.h"
#include "core/files.h"
#include "pipeline/batch_captures.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

int MachineCores(const BatchOptions& options) {
  if (options.cores > 0) return options.cores;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

long long PhysicalMemoryMb() {
  const long long pages = ::sysconf(_SC_PHYS_PAGES), page_bytes = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_bytes > 0 ? pages * page_bytes / (1024 * 1024) : 0;
}

// Snakemake's table of the jobs it plans ("Job stats:" to the end of the table).
std::string JobTable(const std::string& log) {
  const size_t start = log.find("Job stats:");
  if (start == std::string::npos)
    return log.find("Nothing to be done") != std::string::npos ? "Nothing to be done.\n" : "";
  const size_t end = log.find("\n\n", start);
  return log.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
}

// The earliest stage of each capture that a dry run plans, from the jobs snakemake lists
// ("rule compress:" ... "    wildcards: tree=oak").
std::map<std::string, std::string> PlannedStages(const std::string& log) {
  std::map<std::string, std::string> planned;
  std::istringstream lines(log);
  std::string rule;
  const auto order = [](const std::string& stage) {
    return std::find(kBatchStages.begin(), kBatchStages.end(), stage) - kBatchStages.begin();
  };
  for (std::string line; std::getline(lines, line);) {
    for (const char* prefix : {"rule ", "localrule "})
      if (line.rfind(prefix, 0) == 0 && line.back() == ':')
        rule = line.substr(std::string(prefix).size(), line.size() - std::string(prefix).size() - 1);
    const std::string wildcard = "    wildcards: tree=";
    if (line.rfind(wildcard, 0) != 0) continue;
    const std::string tree = line.substr(wildcard.size());
    const auto known = planned.find(tree);
    if (known == planned.end() || order(rule) < order(known->second)) planned[tree] = rule;
  }
  return planned;
}

}  // namespace

void BatchOptions::Check() const {
  if (root.empty()) Fail("batch: no ROOT folder given");
  if (!fs::is_directory(root)) Fail(root.string(), ": no such folder (expected ROOT/TREE/images/ for every tree)");
  if (jobs < 1) Fail("-j ", jobs, ": expected at least 1 job at once");
  if (!fs::is_regular_file(snakefile))
    Fail(snakefile.string(), ": the batch workflow is missing (it ships in the source tree as workflows/Snakefile)");
  if (voltree.empty() || !fs::is_regular_file(voltree)) Fail(voltree.string(), ": the voltree binary is not there");
}

fs::path FindSnakemakeProfile(const std::string& profile, const std::string& home) {
  std::vector<fs::path> candidates = {fs::path(profile)};
  const bool is_name = fs::path(profile).filename() == profile && profile != "." && profile != "..";
  if (is_name) {
    if (!home.empty()) candidates.push_back(fs::path(home) / ".config" / "snakemake" / profile);
    candidates.push_back(fs::path("/etc/xdg/snakemake") / profile);
  }
  std::string looked;
  for (const fs::path& candidate : candidates) {
    if (fs::is_regular_file(candidate / "config.yaml")) return fs::absolute(candidate);
    looked += Str(looked.empty() ? "" : ", ", (candidate / "config.yaml").string());
  }
  Fail("--profile ", profile, ": no such Snakemake profile (looked for ", looked,
       "); a profile is a folder holding config.yaml, see docs/batch.md");
}

std::vector<std::string> SnakemakeArguments(const BatchOptions& options, const fs::path& profile) {
  const fs::path root = fs::absolute(options.root);
  const fs::path snakefile = fs::absolute(options.snakefile);
  std::vector<std::string> args = {"--snakefile",  snakefile.string(),
                                   "--directory",  root.string(),
                                   "--configfile", (snakefile.parent_path() / "config.yaml").string()};
  if (fs::is_regular_file(root / "batch.yaml")) args.push_back((root / "batch.yaml").string());
  args.push_back((root / kBatchFolder / "config.json").string());
  // One failed capture must not stop the others; an interrupted job is redone.
  for (const char* flag : {"--keep-going", "--rerun-incomplete", "--nocolor", "--scheduler", "greedy"})
    args.push_back(flag);
  if (!profile.empty()) {
    args.insert(args.end(), {"--profile", profile.string()});
    if (options.jobs_given) args.insert(args.end(), {"--jobs", std::to_string(options.jobs)});
  } else {
    // This machine's cores shared by `jobs` captures at once; memory as the jobs declare it.
    const int cores = std::max(MachineCores(options), options.jobs);
    args.insert(args.end(),
                {"--cores", std::to_string(cores), "--max-threads", std::to_string(std::max(1, cores / options.jobs))});
    if (const long long memory = PhysicalMemoryMb(); memory > 0)
      args.insert(args.end(), {"--resources", Str("mem_mb=", memory)});
  }
  if (options.dry_run) args.push_back("--dry-run");
  return args;
}

BatchResult RunBatch(const BatchOptions& options, Progress& progress) {
  options.Check();
  const fs::path root = options.root;
  const fs::path snakemake =
      FindExecutable("snakemake", options.search_path,
                     "voltree batch runs its jobs through it; scripts/setup.sh installs it, or: apt-get install "
                     "snakemake");
  const fs::path profile = options.profile.empty() ? fs::path() : FindSnakemakeProfile(options.profile, options.home);
  const BatchFolders folders = FindBatchCaptures(root);
  if (folders.captures.empty()) {
    std::string skipped;
    for (const std::string& name : folders.skipped) skipped += Str(skipped.empty() ? " (" : ", ", name);
    Fail(root.string(), ": no captures; expected a folder per tree holding images/ (ROOT/TREE/images/)",
         skipped.empty() ? "" : Str("; without images/:", skipped, ")"));
  }
  // The batch writes ROOT/scene.json; one there before any batch ran is the user's.
  if (fs::exists(root / "scene.json") && !fs::exists(root / kBatchFolder))
    Fail((root / "scene.json").string(),
         ": exists and was not written by a batch; move it away (the batch writes "
         "the scene of its trees there)");

  BatchResult result;
  fs::create_directories(root / kBatchFolder);
  nlohmann::json config = {{"voltree", fs::absolute(options.voltree).string()}, {"captures", folders.captures}};
  WriteFileAtomic(root / kBatchFolder / "config.json", config.dump(2) + "\n");
  result.snakemake_log = root / kBatchFolder / (options.dry_run ? "dry-run.log" : "snakemake.log");
  progress.Say("batch", Str(options.dry_run ? "planning " : "running ", folders.captures.size(), " captures with ",
                            snakemake.string(), profile.empty() ? "" : " (profile " + profile.string() + ")",
                            "; log: ", result.snakemake_log.string()));
  const fs::file_time_type started = fs::file_time_type::clock::now();
  const ChildResult child = RunChild(snakemake, SnakemakeArguments(options, profile), result.snakemake_log);
  const std::string log = ReadFile(result.snakemake_log);
  result.jobs = JobTable(log);
  result.captures = int(folders.captures.size());

  const std::map<std::string, std::string> planned =
      options.dry_run ? PlannedStages(log) : std::map<std::string, std::string>{};
  for (const std::string& tree : folders.captures) {
    result.rows.push_back(SummarizeCapture(root, tree, options.dry_run));
    if (const auto stage = planned.find(tree); stage != planned.end()) {  // outputs there, but out of date
      result.rows.back().status = CaptureStatus::kPlanned;
      result.rows.back().detail = stage->second;
    }
    // A log older than this run is an earlier failure that snakemake did not get to retry.
    if (result.rows.back().status == CaptureStatus::kFailed && fs::last_write_time(result.rows.back().log) < started) {
      result.rows.back().status = CaptureStatus::kNotRun;
      result.rows.back().log.clear();
    }
    if (result.rows.back().status == CaptureStatus::kFailed) ++result.failed;
  }
  for (const std::string& name : folders.skipped) result.rows.push_back(SkippedFolder(name));
  // Every capture built but no scene: the scene rule failed (a survey CSV it could not use).
  const fs::path scene_log = root / kBatchFolder / "scene.log";
  if (!child.ok() && result.failed == 0 && !fs::exists(root / "scene.json") && fs::exists(scene_log)) {
    result.scene_log = scene_log;
    return result;
  }
  // A failure no capture's log explains is the workflow's own (a locked folder, a bad config).
  if (!child.ok() && result.failed == 0)
    Fail("snakemake failed (", child.signal ? Str("signal ", child.signal) : Str("exit status ", child.exit_code),
         "); the end of its log ", result.snakemake_log.string(), ":\n", LogTail(result.snakemake_log, 25));
  if (!options.dry_run && result.failed == 0 && fs::is_regular_file(root / "scene.json"))
    result.scene = root / "scene.json";
  return result;
}

}  // namespace voltree
