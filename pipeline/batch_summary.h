// What a batch did to each capture, read back from the workspace files the stages wrote (so it is
// the same whether this run or an earlier one built them): status, registered photos, held-out
// PSNR, asset bytes and the seconds of each stage (Snakemake's benchmark files in TREE/logs/).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace voltree {

// The workflow's per-capture stages, in the order they run (workflows/Snakefile).
inline constexpr std::array<const char*, 5> kBatchStages = {"matte", "calibrate", "reconstruct", "compress", "eval"};

enum class CaptureStatus { kBuilt, kFailed, kNotRun, kPlanned, kSkipped };
const char* CaptureStatusName(CaptureStatus status);

struct CaptureSummary {
  std::string tree;
  CaptureStatus status = CaptureStatus::kNotRun;
  std::string detail;                       // the stage that failed or comes next; why a folder was skipped
  std::string log;                          // a failed stage's log (under the batch root)
  int registered = -1;                      // photos with a camera in sparse/ (-1: unknown)
  int photos = -1;                          // photos in images/
  std::optional<double> held_out_rgb_psnr;  // mean over truth/'s views (report/metrics.json)
  std::optional<std::uintmax_t> asset_bytes;
  std::map<std::string, double> stage_seconds;  // stages that ran, by name
};

// `planned`: a dry run, whose missing outputs are to be built rather than failed.
CaptureSummary SummarizeCapture(const std::filesystem::path& root, const std::string& tree, bool planned);
// A folder under the root without images/.
CaptureSummary SkippedFolder(const std::string& name);

// A fixed-width table, one row per capture, and under it the log of every failed capture.
std::string FormatBatchSummary(const std::vector<CaptureSummary>& rows);

}  // namespace voltree
