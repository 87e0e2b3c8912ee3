// MetricsReport: aggregation over views and the JSON it writes.
#include "core/image_metrics_report.h"

#include <gtest/gtest.h>

#include <limits>

namespace voltree {
namespace {

ViewMetrics Metrics(double psnr, double ssim, double precision, double rms) {
  ViewMetrics m;
  m.rgb_psnr = psnr;
  m.rgb_ssim = ssim;
  m.alpha_psnr = psnr + 1;
  m.precision = precision;
  m.recall = 1.0;
  m.rms_per_scale = {rms, rms};
  m.multiscale_rms = rms;
  return m;
}

TEST(MetricsReport, SummarizesMeanMinAndMaxOverViews) {
  MetricsReport report;
  report.Add("view_000.png", Metrics(30, 0.9, 0.8, 0.1));
  report.Add("view_001.png", Metrics(20, 0.7, 1.0, 0.3));
  const auto summaries = report.Summaries();
  ASSERT_EQ(summaries.size(), 6u);
  EXPECT_EQ(summaries[0].first, "rgb_psnr");
  EXPECT_DOUBLE_EQ(summaries[0].second.mean, 25);
  EXPECT_DOUBLE_EQ(summaries[0].second.min, 20);
  EXPECT_DOUBLE_EQ(summaries[0].second.max, 30);
  EXPECT_DOUBLE_EQ(summaries[3].second.mean, 0.9);  // precision
  EXPECT_DOUBLE_EQ(summaries[5].second.min, 0.1);   // multiscale_rms

  const nlohmann::json json = report.ToJson();
  EXPECT_EQ(json["view_count"], 2);
  EXPECT_EQ(json["views"][1]["name"], "view_001.png");
  EXPECT_DOUBLE_EQ(json["summary"]["rgb_ssim"]["mean"].get<double>(), 0.8);
  EXPECT_EQ(json["views"][0]["rms_per_scale"].size(), 2u);
}

TEST(MetricsReport, InfinitePsnrIsWrittenAsNull) {
  MetricsReport report;
  report.Add("same.png", Metrics(std::numeric_limits<double>::infinity(), 1, 1, 0));
  report.Add("other.png", Metrics(40, 0.95, 1, 0.01));
  const nlohmann::json json = report.ToJson();
  EXPECT_TRUE(json["views"][0]["rgb_psnr"].is_null());
  EXPECT_TRUE(json["summary"]["rgb_psnr"]["mean"].is_null());
  EXPECT_TRUE(json["summary"]["rgb_psnr"]["max"].is_null());
  EXPECT_DOUBLE_EQ(json["summary"]["rgb_psnr"]["min"].get<double>(), 40);
  // The dump is a pure function of the report (ordered keys): byte-identical when repeated.
  EXPECT_EQ(json.dump(2), report.ToJson().dump(2));
}

TEST(MetricsReport, EmptyReportHasNoSummary) {
  const nlohmann::json json = MetricsReport{}.ToJson();
  EXPECT_EQ(json["view_count"], 0);
  EXPECT_TRUE(json["summary"].empty());
}

}  // namespace
}  // namespace voltree
