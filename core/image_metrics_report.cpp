#include "core/image_metrics_report.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace voltree {
namespace {

// nlohmann writes non-finite doubles as null already; doing it here makes the contract explicit.
nlohmann::json Number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

MetricSummary Summarize(const std::vector<NamedViewMetrics>& views,
                        const std::function<double(const ViewMetrics&)>& get) {
  MetricSummary summary;
  summary.min = summary.max = get(views.front().metrics);
  double total = 0;  // summed in view order, so the mean is deterministic
  for (const NamedViewMetrics& view : views) {
    const double value = get(view.metrics);
    total += value;
    summary.min = std::min(summary.min, value);
    summary.max = std::max(summary.max, value);
  }
  summary.mean = total / double(views.size());
  return summary;
}

}  // namespace

nlohmann::json ToJson(const ViewMetrics& metrics) {
  nlohmann::json rms = nlohmann::json::array();
  for (double value : metrics.rms_per_scale) rms.push_back(Number(value));
  return {
      {"rgb_psnr", Number(metrics.rgb_psnr)},
      {"rgb_ssim", Number(metrics.rgb_ssim)},
      {"alpha_psnr", Number(metrics.alpha_psnr)},
      {"precision", Number(metrics.precision)},
      {"recall", Number(metrics.recall)},
      {"true_positives", metrics.coverage.true_positives},
      {"false_positives", metrics.coverage.false_positives},
      {"false_negatives", metrics.coverage.false_negatives},
      {"rms_per_scale", rms},
      {"multiscale_rms", Number(metrics.multiscale_rms)},
  };
}

std::vector<std::pair<std::string, MetricSummary>> MetricsReport::Summaries() const {
  if (views.empty()) return {};
  return {
      {"rgb_psnr", Summarize(views, [](const ViewMetrics& m) { return m.rgb_psnr; })},
      {"rgb_ssim", Summarize(views, [](const ViewMetrics& m) { return m.rgb_ssim; })},
      {"alpha_psnr", Summarize(views, [](const ViewMetrics& m) { return m.alpha_psnr; })},
      {"precision", Summarize(views, [](const ViewMetrics& m) { return m.precision; })},
      {"recall", Summarize(views, [](const ViewMetrics& m) { return m.recall; })},
      {"multiscale_rms", Summarize(views, [](const ViewMetrics& m) { return m.multiscale_rms; })},
  };
}

nlohmann::json MetricsReport::ToJson() const {
  nlohmann::json view_list = nlohmann::json::array();
  for (const NamedViewMetrics& view : views) {
    nlohmann::json entry = voltree::ToJson(view.metrics);
    entry["name"] = view.name;
    view_list.push_back(std::move(entry));
  }
  nlohmann::json summary = nlohmann::json::object();
  for (const auto& [name, s] : Summaries())
    summary[name] = {{"mean", Number(s.mean)}, {"min", Number(s.min)}, {"max", Number(s.max)}};
  return {{"view_count", views.size()}, {"views", view_list}, {"summary", summary}};
}

}  // namespace voltree
