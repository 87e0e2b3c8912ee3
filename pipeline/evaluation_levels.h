// Per-level bookkeeping of an evaluation: every render setting compared (the LOD the renderer
// picks by itself, "auto", and each octree level forced) times every view set (held-out truth
// views, input photos), each holding one MetricsReport. "auto" is the overall figure: it is what
// a user of the asset sees; the forced levels show what each level of the hierarchy contributes.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image_metrics.h"
#include "core/image_metrics_report.h"

namespace voltree {

enum class ViewSet { kHeldOut, kInput };
const char* ViewSetName(ViewSet set);  // "held_out", "input" (the JSON keys)

// One render setting: the automatic LOD (forced_level < 0) or exactly one octree level.
struct LevelChoice {
  int forced_level = -1;
  bool IsAuto() const { return forced_level < 0; }
  std::string Name() const;  // "auto", "0", "1", ...
  bool operator==(const LevelChoice&) const = default;
};

// "auto" first, then (when `each_level`) every level 0..level_count-1, coarse to fine.
std::vector<LevelChoice> LevelChoices(int level_count, bool each_level);

class LevelMetricsTable {
 public:
  LevelMetricsTable() = default;
  explicit LevelMetricsTable(std::vector<LevelChoice> choices);

  const std::vector<LevelChoice>& choices() const { return choices_; }
  // Throws Error when `choice` is not one of the table's.
  void Add(const LevelChoice& choice, ViewSet set, std::string view_name, ViewMetrics metrics);
  const MetricsReport& Report(const LevelChoice& choice, ViewSet set) const;
  // The auto LOD's report: the headline numbers. Throws Error when the table has no "auto".
  const MetricsReport& Overall(ViewSet set) const;

  // (level, mean over the set's views of `metric`) for every forced level that has views, coarse
  // to fine: the data of the per-level plots. Non-finite means (an identical view) are left out.
  std::vector<std::pair<int, double>> MeanPerLevel(ViewSet set,
                                                   const std::function<double(const ViewMetrics&)>& metric) const;

  // {"overall": {"held_out": summary, "input": summary},
  //  "levels": [{"level": "auto"|L, "held_out": MetricsReport, "input": MetricsReport}, ...]}
  // Sets without views are absent.
  nlohmann::json ToJson() const;

 private:
  size_t IndexOf(const LevelChoice& choice) const;
  std::vector<LevelChoice> choices_;
  std::vector<MetricsReport> held_out_, input_;  // parallel to choices_
};

// The summary object of a report: {"rgb_psnr": {"mean", "min", "max"}, ...} (null for infinities).
nlohmann::json SummaryJson(const MetricsReport& report);

}  // namespace voltree
