// Which files of a report folder `voltree eval` owns, and whether it may replace them.
//   REPORT/metrics.json  (field "generator": "voltree eval")
//   REPORT/index.html    (<meta name="generator" content="voltree eval">)
//   REPORT/eval/         images, plots and web/ (the web page; holds the marker file .voltree-eval)
// Everything else in REPORT (the demo's contact sheet, orbit frames, benchmark JSON) belongs to
// someone else: eval reads it, links it, and never touches it.
#pragma once

#include <filesystem>
#include <string>

namespace voltree {

inline constexpr const char* kEvalGenerator = "voltree eval";
inline constexpr const char* kMetricsJsonName = "metrics.json";
inline constexpr const char* kIndexHtmlName = "index.html";
inline constexpr const char* kEvalFolderName = "eval";
inline constexpr const char* kEvalMarkerName = ".voltree-eval";
inline constexpr const char* kWebFolderName = "web";  // REPORT/eval/web/: the asset's web page

// Whether an existing file or folder of the report was written by eval (false when it is absent).
bool MetricsJsonByEval(const std::filesystem::path& file);
bool IndexHtmlByEval(const std::filesystem::path& file);
bool EvalFolderByEval(const std::filesystem::path& folder);

// Throws Error naming the first of metrics.json, index.html, eval/ that exists and was not
// written by eval, unless `force`. A report folder that is a file is always an error.
void CheckCanWriteReport(const std::filesystem::path& report, bool force);

}  // namespace voltree
