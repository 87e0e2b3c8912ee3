// Unit tests of the evaluation's bookkeeping: level choices, per-level tables, the JSON they
// become, and which report files eval may replace.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "core/error.h"
#include "core/files.h"
#include "pipeline/evaluation_levels.h"
#include "pipeline/measured_series.h"
#include "pipeline/plots.h"
#include "pipeline/report_folder.h"
#include "pipeline/report_html.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

ViewMetrics Metrics(double rgb_psnr, double alpha_psnr = 20) {
  ViewMetrics m;
  m.rgb_psnr = rgb_psnr;
  m.alpha_psnr = alpha_psnr;
  m.rgb_ssim = 0.5;
  m.precision = m.recall = 0.9;
  m.multiscale_rms = 0.1;
  return m;
}

TEST(LevelChoices, AutoFirstThenEveryLevel) {
  const std::vector<LevelChoice> all = LevelChoices(3, true);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_TRUE(all[0].IsAuto());
  EXPECT_EQ(all[0].Name(), "auto");
  for (int level = 0; level < 3; ++level) EXPECT_EQ(all[level + 1].forced_level, level);
  EXPECT_EQ(all[3].Name(), "2");
  EXPECT_EQ(LevelChoices(3, false).size(), 1u);
  EXPECT_THROW(LevelChoices(0, true), Error);
}

TEST(LevelMetricsTable, KeepsEachLevelAndSetApart) {
  LevelMetricsTable table(LevelChoices(2, true));
  table.Add(LevelChoice{}, ViewSet::kHeldOut, "held_000.png", Metrics(30));
  table.Add(LevelChoice{}, ViewSet::kHeldOut, "held_001.png", Metrics(20));
  table.Add(LevelChoice{0}, ViewSet::kHeldOut, "held_000.png", Metrics(10));
  table.Add(LevelChoice{1}, ViewSet::kHeldOut, "held_000.png", Metrics(24));
  table.Add(LevelChoice{1}, ViewSet::kInput, "view_000.png", Metrics(std::numeric_limits<double>::infinity()));
  table.Add(LevelChoice{0}, ViewSet::kInput, "view_000.png", Metrics(18));
  EXPECT_THROW(table.Add(LevelChoice{5}, ViewSet::kInput, "x", Metrics(1)), Error);

  EXPECT_EQ(table.Overall(ViewSet::kHeldOut).views.size(), 2u);
  EXPECT_TRUE(table.Overall(ViewSet::kInput).views.empty());
  EXPECT_DOUBLE_EQ(table.Overall(ViewSet::kHeldOut).Summaries().front().second.mean, 25.0);

  const auto rgb = [](const ViewMetrics& m) { return m.rgb_psnr; };
  const auto held = table.MeanPerLevel(ViewSet::kHeldOut, rgb);
  ASSERT_EQ(held.size(), 2u);  // the forced levels only, coarse to fine; "auto" is not a level
  EXPECT_EQ(held[0], std::make_pair(0, 10.0));
  EXPECT_EQ(held[1], std::make_pair(1, 24.0));
  const auto input = table.MeanPerLevel(ViewSet::kInput, rgb);
  ASSERT_EQ(input.size(), 1u);  // level 1's infinite PSNR is not a plottable point
  EXPECT_EQ(input[0], std::make_pair(0, 18.0));

  const nlohmann::json json = table.ToJson();
  EXPECT_DOUBLE_EQ(json["overall"]["held_out"]["rgb_psnr"]["mean"].get<double>(), 25.0);
  EXPECT_FALSE(json["overall"].contains("input"));  // no input view at the auto LOD
  ASSERT_EQ(json["levels"].size(), 3u);
  EXPECT_EQ(json["levels"][0]["level"], "auto");
  EXPECT_EQ(json["levels"][2]["level"], 1);
  EXPECT_TRUE(json["levels"][2]["input"]["summary"]["rgb_psnr"]["mean"].is_null());  // infinity
  EXPECT_EQ(json["levels"][1]["held_out"]["views"][0]["name"], "held_000.png");
}

TEST(ReportFolder, ReplacesOnlyWhatEvalWrote) {
  const fs::path dir = fs::temp_directory_path() / ("voltree_report_folder_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_NO_THROW(CheckCanWriteReport(dir, false));  // empty
  WriteFileAtomic(dir / "contact_sheet.png", "not ours, not in the way");
  EXPECT_NO_THROW(CheckCanWriteReport(dir, false));
  WriteFileAtomic(dir / kIndexHtmlName, "<html>my notes</html>");
  EXPECT_THROW(CheckCanWriteReport(dir, false), Error);
  EXPECT_NO_THROW(CheckCanWriteReport(dir, true));
  LevelMetricsTable table(LevelChoices(1, false));
  ReportPage page;
  page.table = &table;
  WriteFileAtomic(dir / kIndexHtmlName, ReportHtml(page));
  EXPECT_TRUE(IndexHtmlByEval(dir / kIndexHtmlName));
  EXPECT_NO_THROW(CheckCanWriteReport(dir, false));
  WriteFileAtomic(dir / kMetricsJsonName, R"({"psnr": 30})");
  EXPECT_THROW(CheckCanWriteReport(dir, false), Error);
  WriteFileAtomic(dir / kMetricsJsonName, R"({"generator": "voltree eval"})");
  EXPECT_NO_THROW(CheckCanWriteReport(dir, false));
  fs::create_directories(dir / kEvalFolderName);
  EXPECT_THROW(CheckCanWriteReport(dir, false), Error);  // an eval/ folder without the marker
  fs::remove_all(dir);
}

TEST(Plots, ScriptQuotesTitlesAndInlinesOnlyMeasuredSeries) {
  PlotSpec spec;
  spec.file = "p.png", spec.title = "it's a title", spec.x_label = "level", spec.y_label = "dB";
  spec.series = {{"held-out", {{0, 10.5}, {1, 20}}}, {"empty", {}}};
  const std::string script = GnuplotScript(spec, "pngcairo", "p.png");
  EXPECT_NE(script.find("set title 'it''s a title'"), std::string::npos) << script;
  EXPECT_NE(script.find("title 'held-out'"), std::string::npos);
  EXPECT_EQ(script.find("'empty'"), std::string::npos);  // a series without points is not plotted
  EXPECT_NE(script.find("0 10.5\n1 20\ne\n"), std::string::npos) << script;
  EXPECT_FALSE(PlotSpec{}.HasPoints());
}

TEST(MeasuredSeries, ReadsPointsGroupedBySeries) {
  const fs::path file = fs::temp_directory_path() / ("voltree_series_" + std::to_string(::getpid()) + ".json");
  EXPECT_TRUE(ReadSeriesFile(file, {"codebook"}, {"rgb_psnr"}, "x").empty());  // absent: no data
  WriteFileAtomic(file, R"({"points": [{"codebook": 512, "rgb_psnr": 30, "series": "vq"},
                                       {"codebook": 64, "psnr": 25, "series": "vq"},
                                       {"colour_codebook": 64, "rgb_psnr": 24}]})");
  const auto series = ReadSeriesFile(file, {"codebook", "colour_codebook"}, {"rgb_psnr", "psnr"}, "default");
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].title, "vq");
  ASSERT_EQ(series[0].points.size(), 2u);
  EXPECT_EQ(series[0].points[0], std::make_pair(64.0, 25.0));  // sorted by x
  EXPECT_EQ(series[1].title, "default");
  WriteFileAtomic(file, R"({"points": [{"codebook": 512}]})");
  EXPECT_THROW(ReadSeriesFile(file, {"codebook"}, {"rgb_psnr"}, "x"), Error);
  fs::remove(file);
}

}  // namespace
}  // namespace voltree
