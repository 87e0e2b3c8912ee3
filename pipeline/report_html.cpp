#include "pipeline/report_html.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "pipeline/report_folder.h"

namespace voltree {

namespace {

std::string Fixed(double value, int digits) {
  if (!std::isfinite(value)) return value > 0 ? "&infin;" : "&ndash;";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

// The mean of each headline metric over a report, as table cells.
std::string SummaryCells(const MetricsReport& report) {
  if (report.views.empty()) return "<td colspan=6>no views</td>";
  std::ostringstream cells;
  for (const auto& [name, summary] : report.Summaries()) {
    const int digits = name == "rgb_psnr" || name == "alpha_psnr" ? 2 : name == "multiscale_rms" ? 4 : 3;
    cells << "<td>" << Fixed(summary.mean, digits) << "</td>";
  }
  return cells.str();
}

const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em;max-width:1400px}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}
th{background:#eee}td:first-child{text-align:left}.note{color:#844}figure{display:inline-block;margin:0 6px 0 0}
figure img{width:256px;image-rendering:pixelated}figure iframe{border:0;vertical-align:top}figcaption{font-size:85%;text-align:center}
.strip img{width:96px;margin-right:2px}.plots img{max-width:640px;margin:0 1em 1em 0})";

const char* kMetricHeader =
    "<th>RGB PSNR (dB)</th><th>SSIM</th><th>alpha PSNR (dB)</th><th>precision</th><th>recall</th><th>multi-scale "
    "RMS</th>";

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string ReportHtml(const ReportPage& page) {
  if (!page.table) Fail("report page: no metrics table");
  const LevelMetricsTable& table = *page.table;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n<meta name=\"generator\" content=\"" << kEvalGenerator
       << "\">\n<title>" << HtmlEscape(page.title) << "</title>\n<style>" << kStyle << "</style></head><body>\n";
  html << "<h1>" << HtmlEscape(page.title) << "</h1>\n<table>\n";
  for (const auto& [what, value] : page.facts)
    html << "<tr><td>" << HtmlEscape(what) << "</td><td style=\"text-align:left\">" << HtmlEscape(value)
         << "</td></tr>\n";
  html << "</table>\n";
  for (const std::string& note : page.notes) html << "<p class=\"note\">" << HtmlEscape(note) << "</p>\n";

  html << "<h2>Overall (the renderer's own level of detail)</h2>\n<p>RGB metrics compare both images composited over "
          "the same fixed grey; precision and recall count pixels with alpha &gt; 0.5 (Neubert et al. 2011); the "
          "multi-scale RMS is the mean RMS of the composite difference over a 2&times;2 box pyramid (Clasen et al. "
          "2011). Means over the views.</p>\n";
  html << "<table><tr><th>views</th><th>count</th>" << kMetricHeader << "</tr>\n";
  for (ViewSet set : {ViewSet::kHeldOut, ViewSet::kInput}) {
    const MetricsReport& report = table.Overall(set);
    if (report.views.empty()) continue;
    html << "<tr><td>" << (set == ViewSet::kHeldOut ? "held-out (truth)" : "input (self-consistency)") << "</td><td>"
         << report.views.size() << "</td>" << SummaryCells(report) << "</tr>\n";
  }
  html << "</table>\n";

  if (!page.budget.empty()) {
    html << "<h2>Error budget</h2>\n<p>What each step costs (eval --budget): <em>volume</em> is the finest level's "
            "densities ray-marched (alpha only); <em>billboards</em> its uncompressed billboards drawn as the renderer "
            "draws them (CPU); <em>vq</em> with the codewords; <em>dxt5</em> as fetched from the atlas; <em>lod</em> "
            "the asset drawn by the GPU with its level of detail.</p>\n";
    html << "<table><tr><th>step</th><th>views</th><th>count</th><th>RGB PSNR</th><th>alpha PSNR</th><th>P</th>"
            "<th>R</th><th>bark R</th><th>leaf R</th></tr>\n";
    for (const BudgetRow& row : page.budget)
      html << "<tr><td>" << HtmlEscape(row.step) << "</td><td>" << ViewSetName(row.set) << "</td><td>" << row.views
           << "</td><td>" << (std::isnan(row.rgb_psnr) ? "&ndash;" : Fixed(row.rgb_psnr, 2)) << "</td><td>"
           << Fixed(row.alpha_psnr, 2) << "</td><td>" << Fixed(row.precision, 3) << "</td><td>" << Fixed(row.recall, 3)
           << "</td><td>" << (std::isnan(row.bark_recall) ? "&ndash;" : Fixed(row.bark_recall, 3)) << "</td><td>"
           << (std::isnan(row.leaf_recall) ? "&ndash;" : Fixed(row.leaf_recall, 3)) << "</td></tr>\n";
    html << "</table>\n";
  }

  html << "<h2>Per level</h2>\n<p><em>auto</em> is the renderer's LOD; a number draws only that octree level.</p>\n";
  html << "<table><tr><th>level</th><th>views</th>" << kMetricHeader << "<th>pruned %</th></tr>\n";
  for (const LevelChoice& choice : table.choices()) {
    for (ViewSet set : {ViewSet::kHeldOut, ViewSet::kInput}) {
      const MetricsReport& report = table.Report(choice, set);
      if (report.views.empty()) continue;
      const auto pruned = page.pruned_percent.find(choice.forced_level);
      html << "<tr><td>" << HtmlEscape(choice.Name()) << "</td><td>" << ViewSetName(set) << "</td>"
           << SummaryCells(report) << "<td>"
           << (pruned != page.pruned_percent.end() && set == ViewSet::kHeldOut ? Fixed(pruned->second, 1) : "")
           << "</td></tr>\n";
    }
  }
  html << "</table>\n";

  if (!page.plots.empty()) {
    html << "<h2>Plots</h2>\n<div class=\"plots\">\n";
    for (const HtmlLink& plot : page.plots)
      html << "<img src=\"" << HtmlEscape(plot.href) << "\" alt=\"" << HtmlEscape(plot.text) << "\" title=\""
           << HtmlEscape(plot.text) << "\">\n";
    html << "</div>\n";
  }

  if (!page.comparisons.empty()) {
    const bool interactive = !page.comparisons.front().interactive.empty();
    html << "<h2>Held-out views</h2>\n<p>truth | "
         << (interactive ? "voltree (interactive: the web page, eval/web/) | " : "")
         << "voltree (auto LOD) | difference &times;" << Fixed(page.difference_gain, 0)
         << " (black: equal), all over the evaluation's grey.</p>\n";
    for (const HtmlComparison& c : page.comparisons) {
      html << "<div><h3>" << HtmlEscape(c.view) << "</h3>\n";
      const std::pair<const std::string*, const char*> images[] = {
          {&c.truth, "truth"}, {&c.render, "voltree"}, {&c.difference, "difference"}};
      for (const auto& [src, caption] : images) {
        html << "<figure><a href=\"" << HtmlEscape(*src) << "\"><img src=\"" << HtmlEscape(*src) << "\" alt=\""
             << caption << "\"></a><figcaption>" << caption << "</figcaption></figure>\n";
        if (src == &c.truth && !c.interactive.empty())  // beside the truth: the web page at this camera, to turn
          html << "<figure><iframe src=\"" << HtmlEscape(c.interactive) << "\" title=\"voltree (interactive)\" "
               << "width=\"256\" height=\"" << c.interactive_height << "\" loading=\"lazy\"></iframe><figcaption>"
               << "voltree (interactive: drag, wheel)</figcaption></figure>\n";
      }
      html << "<p>RGB PSNR " << Fixed(c.metrics.rgb_psnr, 2) << " dB, SSIM " << Fixed(c.metrics.rgb_ssim, 3)
           << ", alpha PSNR " << Fixed(c.metrics.alpha_psnr, 2) << " dB, P " << Fixed(c.metrics.precision, 3) << ", R "
           << Fixed(c.metrics.recall, 3) << ", RMS " << Fixed(c.metrics.multiscale_rms, 4) << "</p></div>\n";
    }
  }

  if (!page.thumbnails.empty()) {
    html << "<h2>Orbit</h2>\n<div class=\"strip\">";
    for (const std::string& frame : page.thumbnails)
      html << "<a href=\"" << HtmlEscape(frame) << "\"><img src=\"" << HtmlEscape(frame)
           << "\" alt=\"orbit frame\"></a>";
    html << "</div>\n";
  }
  if (!page.links.empty()) {
    html << "<h2>Files</h2>\n<ul>\n";
    for (const HtmlLink& link : page.links)
      html << "<li><a href=\"" << HtmlEscape(link.href) << "\">" << HtmlEscape(link.text) << "</a></li>\n";
    html << "</ul>\n";
  }
  html << "</body></html>\n";
  return html.str();
}

}  // namespace voltree
