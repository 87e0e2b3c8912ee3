// Metrics of several views gathered into one report, with mean and min over the views, written
// as the JSON of metrics.json.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/image_metrics.h"

namespace voltree {

// One named metric over all views. A PSNR of +infinity (an identical view) makes the mean
// +infinity too; JSON writes infinities as null.
struct MetricSummary {
  double mean = 0;
  double min = 0;
  double max = 0;
};

struct NamedViewMetrics {
  std::string name;  // image name, e.g. "view_000.png"
  ViewMetrics metrics;
};

struct MetricsReport {
  std::vector<NamedViewMetrics> views;

  void Add(std::string name, ViewMetrics metrics) { views.push_back({std::move(name), std::move(metrics)}); }
  // Mean, min and max over the views of rgb_psnr, rgb_ssim, alpha_psnr, precision, recall and
  // multiscale_rms, in that order of keys; empty when there are no views.
  std::vector<std::pair<std::string, MetricSummary>> Summaries() const;
  // {"views": [{"name":..., "rgb_psnr":..., ...}], "summary": {"rgb_psnr": {"mean":..,"min":..,"max":..}, ...}}
  // Infinite PSNR (identical images) is written as null, the only JSON value that cannot be
  // mistaken for a measured figure.
  nlohmann::json ToJson() const;
};

// One view's metrics as JSON (infinite values as null).
nlohmann::json ToJson(const ViewMetrics& metrics);

}  // namespace voltree
