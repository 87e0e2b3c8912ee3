#include "pipeline/evaluation_report.h"

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "pipeline/report_folder.h"

namespace voltree {
namespace {

using nlohmann::json;

json Finite(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json SettingsJson(const EvaluationReport& report) {
  return {{"background_grey", report.metrics.background_grey},
          {"coverage_threshold", report.metrics.coverage_threshold},
          {"ssim_window", report.metrics.ssim_window},
          {"ssim_sigma", report.metrics.ssim_sigma},
          {"lod_rule", LodRuleName(report.lod.rule)},
          {"max_texel_pixels", report.lod.max_texel_pixels},
          {"lod_history", false},
          {"levels", report.asset.levels}};
}

json AlignmentJson(const std::optional<TruthAlignment>& alignment) {
  if (!alignment) return nullptr;
  const Similarity& s = alignment->truth_to_workspace;
  return {{"from", "truth/input_sparse"},
          {"to", "sparse"},
          {"scale", s.scale},
          {"rotation_wxyz", {s.rotation.w(), s.rotation.x(), s.rotation.y(), s.rotation.z()}},
          {"translation", {s.translation.x(), s.translation.y(), s.translation.z()}},
          {"matched_views", alignment->matched_views},
          {"mean_rotation_degrees", alignment->mean_rotation_degrees},
          {"mean_center_error", alignment->mean_center_error}};
}

json BudgetJson(const std::vector<BudgetRow>& budget) {
  json rows = json::array();
  for (const BudgetRow& row : budget)
    rows.push_back({{"step", row.step},
                    {"views", ViewSetName(row.set)},
                    {"count", row.views},
                    {"rgb_psnr", Finite(row.rgb_psnr)},
                    {"alpha_psnr", Finite(row.alpha_psnr)},
                    {"precision", row.precision},
                    {"recall", row.recall},
                    {"bark_recall", Finite(row.bark_recall)},
                    {"leaf_recall", Finite(row.leaf_recall)}});
  return rows;
}

json PruningJson(const PruningStats& pruning) {
  json levels = json::array();
  for (const LevelPruning& level : pruning.levels)
    levels.push_back({{"level", level.level},
                      {"billboards_before_pruning", level.billboards_before_pruning},
                      {"billboards", level.billboards},
                      {"pruned_percent", Finite(level.pruned_percent)}});
  return {{"source", pruning.source}, {"levels", levels}};
}

json AssetStatsJson(const EvaluatedAsset& asset) {
  return {{"bytes", asset.bytes},
          {"cells", asset.cells},
          {"billboards", asset.billboards},
          {"colour_codebook", asset.colour_codebook},
          {"alpha_codebook", asset.alpha_codebook}};
}

json ImagesJson(const std::vector<ComparisonFiles>& comparisons) {
  json images = json::array();
  for (const ComparisonFiles& files : comparisons)
    images.push_back(
        {{"view", files.view}, {"truth", files.truth}, {"render", files.render}, {"difference", files.difference}});
  return images;
}

std::vector<std::pair<std::string, std::string>> PageFacts(const EvaluationReport& report) {
  const EvaluatedAsset& asset = report.asset;
  std::vector<std::pair<std::string, std::string>> facts = {
      {"workspace", report.workspace},
      {"asset", Str(asset.name, " (", asset.bytes, " bytes, ", asset.levels, " levels, ", asset.billboards,
                    " billboards, codebooks ", asset.colour_codebook, " colour / ", asset.alpha_codebook, " alpha)")},
      {"renderer", report.renderer},
      {"background", Str("grey ", report.metrics.background_grey, " (8-bit), LOD rule ", LodRuleName(report.lod.rule),
                         ", ", report.lod.max_texel_pixels, " px per texel")}};
  if (report.alignment)
    facts.push_back({"truth alignment", Str("held-out cameras moved into the calibrated frame by a similarity fit to ",
                                            report.alignment->matched_views, " input cameras; residual ",
                                            report.alignment->mean_rotation_degrees, " deg, centre error ",
                                            report.alignment->mean_center_error, " of the camera distance")});
  return facts;
}

}  // namespace

json MetricsJson(const EvaluationReport& report) {
  json doc = report.table.ToJson();
  doc["generator"] = kEvalGenerator;
  doc["format_version"] = 1;
  doc["workspace"] = report.workspace;
  doc["asset"] = report.asset.name;
  doc["renderer"] = report.renderer;
  doc["settings"] = SettingsJson(report);
  doc["view_counts"] = {{"held_out", report.held_out_views}, {"input", report.input_views}};
  doc["truth_alignment"] = AlignmentJson(report.alignment);
  if (!report.budget.empty()) doc["budget"] = BudgetJson(report.budget);
  doc["pruning"] = PruningJson(report.pruning);
  doc["asset_stats"] = AssetStatsJson(report.asset);
  doc["images"] = ImagesJson(report.comparisons);
  doc["plots"] = report.plots;
  doc["notes"] = report.notes;
  return doc;
}

ReportPage EvaluationPage(const EvaluationReport& report, std::vector<std::string> thumbnails, bool contact_sheet) {
  ReportPage page;
  page.title = Str("voltree evaluation: ", report.workspace);
  page.facts = PageFacts(report);
  page.notes = report.notes;
  page.table = &report.table;
  for (const LevelPruning& level : report.pruning.levels) page.pruned_percent[level.level] = level.pruned_percent;
  for (size_t v = 0; v < report.comparisons.size(); ++v) {
    const ComparisonFiles& files = report.comparisons[v];
    HtmlComparison comparison{files.view,
                              files.truth,
                              files.render,
                              files.difference,
                              report.table.Overall(ViewSet::kHeldOut).views[v].metrics,
                              files.interactive,
                              files.interactive_height};
    page.comparisons.push_back(std::move(comparison));
  }
  page.difference_gain = report.difference_gain;
  for (const std::string& plot : report.plots)
    page.plots.push_back({plot, std::filesystem::path(plot).stem().string()});
  page.thumbnails = std::move(thumbnails);
  page.budget = report.budget;
  page.links.push_back({kMetricsJsonName, "metrics.json (every view, every level)"});
  if (contact_sheet) page.links.push_back({"contact_sheet.png", "contact sheet of the input photos"});
  if (!page.thumbnails.empty()) page.links.push_back({"orbit/", "orbit frames"});
  return page;
}

}  // namespace voltree
