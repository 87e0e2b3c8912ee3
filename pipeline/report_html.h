// The evaluation report page, REPORT/index.html: one self-contained HTML file (inline CSS, no
// scripts) with the headline table, the per-level table, the side-by-side images of every
// held-out view (truth | voltree | difference, PNG files in REPORT/eval/; and the interactive
// web page in a frame, REPORT/eval/web/, when written) and the plots.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/image_metrics.h"
#include "pipeline/error_budget.h"
#include "pipeline/evaluation_levels.h"

namespace voltree {

struct HtmlComparison {
  std::string view;                       // the view's image name
  std::string truth, render, difference;  // paths relative to the page
  ViewMetrics metrics;
  std::string interactive;       // the web page at this view's camera (URL relative to the page), or empty
  int interactive_height = 256;  // the frame's height for a width of 256 (the camera's aspect)
};

struct HtmlLink {
  std::string href;  // relative to the page
  std::string text;
};

struct ReportPage {
  std::string title = "voltree evaluation";
  std::vector<std::pair<std::string, std::string>> facts;  // (what, value): asset, renderer, ...
  std::vector<std::string> notes;                          // caveats, e.g. plots skipped, alignment
  const LevelMetricsTable* table = nullptr;                // required
  std::map<int, double> pruned_percent;                    // per level, when known
  std::vector<HtmlComparison> comparisons;                 // held-out views, auto LOD
  float difference_gain = 4;
  std::vector<HtmlLink> plots;          // PNG files
  std::vector<HtmlLink> links;          // contact sheet, orbit frames, metrics.json
  std::vector<std::string> thumbnails;  // a strip of orbit frames, when present
  std::vector<BudgetRow> budget;        // eval --budget: what each step costs
};

// "&<>\"'" escaped.
std::string HtmlEscape(const std::string& text);

// The whole page; marked <meta name="generator" content="voltree eval"> (report_folder.h).
std::string ReportHtml(const ReportPage& page);

}  // namespace voltree
