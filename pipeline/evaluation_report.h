// What an evaluation found, and the two files that present it: REPORT/metrics.json (MetricsJson:
// deterministic for a given asset and renderer, no timings) and REPORT/index.html
// (EvaluationPage, drawn by report_html.h). Both are pure functions of EvaluationReport.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image_metrics.h"
#include "pipeline/error_budget.h"
#include "pipeline/evaluation_levels.h"
#include "pipeline/evaluation_renders.h"
#include "pipeline/evaluation_truth.h"
#include "pipeline/measured_series.h"
#include "pipeline/report_html.h"
#include "render/lod.h"

namespace voltree {

struct EvaluatedAsset {
  std::string name;  // relative to the workspace when inside it
  uintmax_t bytes = 0;
  size_t levels = 0, cells = 0, billboards = 0;
  uint32_t colour_codebook = 0, alpha_codebook = 0;
};

struct EvaluationReport {
  std::string workspace;  // as the page and metrics.json name it
  EvaluatedAsset asset;
  std::string renderer;  // GL_RENDERER
  ImageMetricsOptions metrics;
  LodOptions lod;
  float difference_gain = 4;
  size_t held_out_views = 0, input_views = 0;
  std::optional<TruthAlignment> alignment;
  LevelMetricsTable table;
  std::vector<BudgetRow> budget;
  PruningStats pruning;
  std::vector<ComparisonFiles> comparisons;
  std::vector<std::string> plots;  // relative to the report folder
  std::vector<std::string> notes;
};

nlohmann::json MetricsJson(const EvaluationReport& report);

// The page of `report`, which it points into. `thumbnails`: orbit frames relative to the report
// folder; `contact_sheet`: whether REPORT/contact_sheet.png exists.
ReportPage EvaluationPage(const EvaluationReport& report, std::vector<std::string> thumbnails, bool contact_sheet);

}  // namespace voltree
