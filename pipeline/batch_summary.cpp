#include "pipeline/batch_summary.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "capture/calibrate.h"
#include "capture/colmap_binary.h"
#include "capture/photo_folder.h"
#include "core/colmap_model.h"
#include "core/error.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// What each stage leaves in the workspace; a stage whose output is missing has not finished.
fs::path StageOutput(const std::string& stage) {
  if (stage == "matte") return "mattes";
  if (stage == "calibrate") return "sparse";
  if (stage == "reconstruct") return "volume";
  if (stage == "compress") return "tree.vtree";
  return fs::path("report") / "metrics.json";
}

// The "s" column of a Snakemake benchmark file (a header line, then one line per repeat).
std::optional<double> BenchmarkSeconds(const fs::path& tsv) {
  std::ifstream in(tsv);
  std::string header, values;
  if (!std::getline(in, header) || !std::getline(in, values)) return std::nullopt;
  std::istringstream fields(values);
  double seconds = 0;
  if (header.rfind("s\t", 0) != 0 || !(fields >> seconds)) return std::nullopt;
  return seconds;
}

std::optional<double> HeldOutPsnr(const fs::path& metrics) {
  try {
    const nlohmann::json doc = nlohmann::json::parse(std::ifstream(metrics));
    const nlohmann::json& psnr = doc.at("overall").at("held_out").at("rgb_psnr").at("mean");
    if (psnr.is_number()) return psnr.get<double>();
  } catch (const std::exception&) {  // no held-out views, or not eval's file: nothing to show
  }
  return std::nullopt;
}

std::string Cell(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

const char* CaptureStatusName(CaptureStatus status) {
  switch (status) {
    case CaptureStatus::kBuilt:
      return "built";
    case CaptureStatus::kFailed:
      return "FAILED";
    case CaptureStatus::kNotRun:
      return "not run";
    case CaptureStatus::kPlanned:
      return "to do";
    case CaptureStatus::kSkipped:
      return "skipped";
  }
  return "?";
}

CaptureSummary SummarizeCapture(const fs::path& root, const std::string& tree, bool planned) {
  const fs::path dir = root / tree;
  CaptureSummary summary;
  summary.tree = tree;
  summary.photos = int(FindPhotos(dir / "images").size());
  try {
    if (fs::is_directory(dir / "sparse")) summary.registered = int(ReadColmapModel(dir / "sparse").Views().size());
  } catch (const Error&) {  // an unreadable model shows as unknown; its stage's log says why
  }
  if (fs::is_regular_file(dir / "tree.vtree")) summary.asset_bytes = fs::file_size(dir / "tree.vtree");
  summary.held_out_rgb_psnr = HeldOutPsnr(dir / "report" / "metrics.json");
  for (const char* stage : kBatchStages)
    if (const auto seconds = BenchmarkSeconds(dir / "logs" / (std::string(stage) + ".tsv")))
      summary.stage_seconds[stage] = *seconds;

  const bool with_truth = fs::is_directory(dir / "truth");
  summary.status = CaptureStatus::kBuilt;
  for (const char* stage : kBatchStages) {
    if (std::string(stage) == "eval" && !with_truth) break;
    if (fs::exists(dir / StageOutput(stage))) continue;
    summary.detail = stage;
    const fs::path log = fs::path(tree) / "logs" / (std::string(stage) + ".log");
    if (planned) {
      summary.status = CaptureStatus::kPlanned;
    } else if (fs::exists(root / log)) {
      summary.status = CaptureStatus::kFailed;
      summary.log = (root / log).string();
    } else {
      summary.status = CaptureStatus::kNotRun;
    }
    break;
  }
  return summary;
}

CaptureSummary SkippedFolder(const std::string& name) {
  CaptureSummary summary;
  summary.tree = name;
  summary.status = CaptureStatus::kSkipped;
  summary.detail = "no images/";
  return summary;
}

std::string FormatBatchSummary(const std::vector<CaptureSummary>& rows) {
  std::vector<std::vector<std::string>> table = {{"tree", "status", "registered", "held-out PSNR", "asset bytes"}};
  for (const char* stage : kBatchStages) table[0].push_back(std::string(stage) + " s");
  for (const CaptureSummary& row : rows) {
    std::string status = CaptureStatusName(row.status);
    if (!row.detail.empty()) status += " (" + row.detail + ")";
    std::vector<std::string> cells = {row.tree, status,
                                      row.registered >= 0 ? Str(row.registered, "/", row.photos) : "-",
                                      row.held_out_rgb_psnr ? Cell(*row.held_out_rgb_psnr, 2) + " dB" : "-",
                                      row.asset_bytes ? std::to_string(*row.asset_bytes) : "-"};
    for (const char* stage : kBatchStages) {
      const auto seconds = row.stage_seconds.find(stage);
      cells.push_back(seconds == row.stage_seconds.end() ? "-" : Cell(seconds->second, 1));
    }
    table.push_back(cells);
  }
  std::vector<size_t> widths(table[0].size(), 0);
  for (const auto& cells : table)
    for (size_t i = 0; i < cells.size(); ++i) widths[i] = std::max(widths[i], cells[i].size());
  std::string text;
  for (const auto& cells : table) {
    std::string line;
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string padding(widths[i] - cells[i].size(), ' ');
      line += i < 2 ? cells[i] + padding : padding + cells[i];  // names left, numbers right
      if (i + 1 < cells.size()) line += "  ";
    }
    text += line + "\n";
  }
  for (const CaptureSummary& row : rows)
    if (row.status == CaptureStatus::kFailed) text += Str(row.tree, ": ", row.detail, " failed; log: ", row.log, "\n");
  return text;
}

}  // namespace voltree
