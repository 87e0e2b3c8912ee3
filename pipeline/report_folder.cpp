#include "pipeline/report_folder.h"

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

bool MetricsJsonByEval(const fs::path& file) {
  if (!fs::is_regular_file(file)) return false;
  const nlohmann::json doc = nlohmann::json::parse(ReadFile(file), nullptr, /*allow_exceptions=*/false);
  return doc.is_object() && doc.value("generator", "") == kEvalGenerator;
}

bool IndexHtmlByEval(const fs::path& file) {
  if (!fs::is_regular_file(file)) return false;
  return ReadFile(file).find(Str("<meta name=\"generator\" content=\"", kEvalGenerator, "\">")) != std::string::npos;
}

bool EvalFolderByEval(const fs::path& folder) { return fs::is_regular_file(folder / kEvalMarkerName); }

void CheckCanWriteReport(const fs::path& report, bool force) {
  if (fs::exists(report) && !fs::is_directory(report)) Fail(report.string(), ": exists and is not a folder");
  if (force) return;
  const fs::path metrics = report / kMetricsJsonName, index = report / kIndexHtmlName,
                 folder = report / kEvalFolderName;
  const char* hint = " was not written by 'voltree eval'; pass --force to replace it (or choose --report DIR)";
  if (fs::exists(metrics) && !MetricsJsonByEval(metrics)) Fail(metrics.string(), hint);
  if (fs::exists(index) && !IndexHtmlByEval(index)) Fail(index.string(), hint);
  if (fs::exists(folder) && !EvalFolderByEval(folder)) Fail(folder.string(), hint);
}

}  // namespace voltree
