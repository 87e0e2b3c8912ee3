#include "pipeline/evaluation_levels.h"

#include <cmath>

#include "core/error.h"

namespace voltree {

const char* ViewSetName(ViewSet set) { return set == ViewSet::kHeldOut ? "held_out" : "input"; }

std::string LevelChoice::Name() const { return IsAuto() ? "auto" : std::to_string(forced_level); }

std::vector<LevelChoice> LevelChoices(int level_count, bool each_level) {
  if (level_count < 1) Fail("evaluate: the asset has no levels");
  std::vector<LevelChoice> choices = {LevelChoice{}};
  if (each_level)
    for (int level = 0; level < level_count; ++level) choices.push_back(LevelChoice{level});
  return choices;
}

LevelMetricsTable::LevelMetricsTable(std::vector<LevelChoice> choices)
    : choices_(std::move(choices)), held_out_(choices_.size()), input_(choices_.size()) {}

size_t LevelMetricsTable::IndexOf(const LevelChoice& choice) const {
  for (size_t i = 0; i < choices_.size(); ++i)
    if (choices_[i] == choice) return i;
  Fail("evaluate: level '", choice.Name(), "' is not among the evaluated levels");
}

void LevelMetricsTable::Add(const LevelChoice& choice, ViewSet set, std::string view_name, ViewMetrics metrics) {
  const size_t i = IndexOf(choice);
  (set == ViewSet::kHeldOut ? held_out_ : input_)[i].Add(std::move(view_name), std::move(metrics));
}

const MetricsReport& LevelMetricsTable::Report(const LevelChoice& choice, ViewSet set) const {
  const size_t i = IndexOf(choice);
  return (set == ViewSet::kHeldOut ? held_out_ : input_)[i];
}

const MetricsReport& LevelMetricsTable::Overall(ViewSet set) const { return Report(LevelChoice{}, set); }

std::vector<std::pair<int, double>> LevelMetricsTable::MeanPerLevel(
    ViewSet set, const std::function<double(const ViewMetrics&)>& metric) const {
  std::vector<std::pair<int, double>> points;
  for (size_t i = 0; i < choices_.size(); ++i) {
    if (choices_[i].IsAuto()) continue;
    const MetricsReport& report = (set == ViewSet::kHeldOut ? held_out_ : input_)[i];
    if (report.views.empty()) continue;
    double total = 0;
    for (const NamedViewMetrics& view : report.views) total += metric(view.metrics);
    const double mean = total / double(report.views.size());
    if (std::isfinite(mean)) points.emplace_back(choices_[i].forced_level, mean);
  }
  return points;
}

nlohmann::json SummaryJson(const MetricsReport& report) { return report.ToJson().at("summary"); }

nlohmann::json LevelMetricsTable::ToJson() const {
  nlohmann::json overall = nlohmann::json::object();
  nlohmann::json levels = nlohmann::json::array();
  for (size_t i = 0; i < choices_.size(); ++i) {
    nlohmann::json entry = {
        {"level", choices_[i].IsAuto() ? nlohmann::json("auto") : nlohmann::json(choices_[i].forced_level)}};
    for (ViewSet set : {ViewSet::kHeldOut, ViewSet::kInput}) {
      const MetricsReport& report = (set == ViewSet::kHeldOut ? held_out_ : input_)[i];
      if (report.views.empty()) continue;
      entry[ViewSetName(set)] = report.ToJson();
      if (choices_[i].IsAuto()) overall[ViewSetName(set)] = SummaryJson(report);
    }
    levels.push_back(std::move(entry));
  }
  return {{"overall", overall}, {"levels", levels}};
}

}  // namespace voltree
