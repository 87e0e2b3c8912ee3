// The evaluation report's two files as pure functions of what was measured: metrics.json and the
// page both name every compared image with its view, and the page's links follow what exists.
#include "pipeline/evaluation_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/evaluation_renders.h"

namespace voltree {
namespace {

EvaluationReport TwoViewReport() {
  EvaluationReport report;
  report.workspace = "oak";
  report.asset = {"tree.vtree", 1234, 3, 40, 90, 64, 32};
  report.renderer = "test renderer";
  report.held_out_views = 2;
  report.table = LevelMetricsTable(LevelChoices(3, false));
  for (const char* view : {"held/a.png", "held/b.png"}) {
    ViewMetrics metrics;
    metrics.rgb_psnr = view[5] == 'a' ? 31 : 27;
    report.table.Add(LevelChoice{}, ViewSet::kHeldOut, view, metrics);
    const std::string stem = "eval/held_out/" + FlatStem(view);
    ComparisonFiles files;
    files.view = view;
    files.truth = stem + "_truth.png";
    files.render = stem + "_voltree.png";
    files.difference = stem + "_difference.png";
    report.comparisons.push_back(files);
  }
  report.pruning.levels = {{0, 10, 8, 20.0}, {1, 4, 4, NAN}};
  return report;
}

TEST(EvaluationReport, MetricsJsonNamesEveryImageAndLeavesOutWhatWasNotMeasured) {
  const nlohmann::json json = MetricsJson(TwoViewReport());
  ASSERT_EQ(json["images"].size(), 2u);
  EXPECT_EQ(json["images"][1]["view"], "held/b.png");
  EXPECT_EQ(json["images"][1]["difference"], "eval/held_out/held_b_difference.png");
  EXPECT_EQ(json["asset"], "tree.vtree");
  EXPECT_EQ(json["asset_stats"]["billboards"], 90);
  EXPECT_EQ(json["settings"]["levels"], 3);
  EXPECT_EQ(json["view_counts"]["held_out"], 2);
  EXPECT_TRUE(json["truth_alignment"].is_null());
  EXPECT_FALSE(json.contains("budget"));                                  // not measured
  EXPECT_TRUE(json["pruning"]["levels"][1]["pruned_percent"].is_null());  // NaN is not JSON
}

TEST(EvaluationReport, PageShowsEachComparisonWithItsViewsMetrics) {
  const EvaluationReport report = TwoViewReport();
  const ReportPage page = EvaluationPage(report, {"orbit/frame_000.png"}, /*contact_sheet=*/false);
  EXPECT_EQ(page.title, "voltree evaluation: oak");
  EXPECT_EQ(page.table, &report.table);
  ASSERT_EQ(page.comparisons.size(), 2u);
  EXPECT_EQ(page.comparisons[0].view, "held/a.png");
  EXPECT_EQ(page.comparisons[0].metrics.rgb_psnr, 31);
  EXPECT_EQ(page.comparisons[1].metrics.rgb_psnr, 27);
  EXPECT_EQ(page.facts[1].second, "tree.vtree (1234 bytes, 3 levels, 90 billboards, codebooks 64 colour / 32 alpha)");
  EXPECT_EQ(page.pruned_percent.at(0), 20.0);
  ASSERT_EQ(page.links.size(), 2u);  // metrics.json and the orbit; no contact sheet
  EXPECT_EQ(page.links[1].href, "orbit/");
  EXPECT_EQ(EvaluationPage(report, {}, true).links.back().href, "contact_sheet.png");
}

}  // namespace
}  // namespace voltree
