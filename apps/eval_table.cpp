#include "apps/eval_table.h"

#include <cstdio>

#include "core/error.h"

namespace voltree::app {

std::string EvaluationTable(const LevelMetricsTable& table) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-9s %5s %9s %6s %11s %6s %6s %7s\n", "views", "count", "RGB PSNR", "SSIM",
                "alpha PSNR", "P", "R", "RMS");
  out += line;
  for (ViewSet set : {ViewSet::kHeldOut, ViewSet::kInput}) {
    const MetricsReport& report = table.Overall(set);
    if (report.views.empty()) continue;
    double mean[6] = {};
    const auto summaries = report.Summaries();  // rgb_psnr, rgb_ssim, alpha_psnr, precision, recall, multiscale_rms
    for (size_t i = 0; i < 6 && i < summaries.size(); ++i) mean[i] = summaries[i].second.mean;
    std::snprintf(line, sizeof line, "%-9s %5zu %9.2f %6.3f %11.2f %6.3f %6.3f %7.4f\n", ViewSetName(set),
                  report.views.size(), mean[0], mean[1], mean[2], mean[3], mean[4], mean[5]);
    out += line;
  }
  return out;
}

void PrintEvaluation(const EvaluateResult& result) {
  std::printf("%s", EvaluationTable(result.table).c_str());
  for (const std::string& note : result.notes) std::printf("note: %s\n", note.c_str());
  std::printf("%s\n", result.index_html.string().c_str());
}

}  // namespace voltree::app
