#include "pipeline/measured_series.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

nlohmann::json ParseJsonFile(const fs::path& file) {
  try {
    return nlohmann::json::parse(ReadFile(file));
  } catch (const nlohmann::json::exception& e) {
    Fail(file.string(), ": not valid JSON: ", e.what());
  }
}

const nlohmann::json* FirstNumber(const nlohmann::json& point, const std::vector<std::string>& keys) {
  for (const std::string& key : keys) {
    const auto found = point.find(key);
    if (found != point.end() && found->is_number()) return &*found;
  }
  return nullptr;
}

}  // namespace

PruningStats ReadPruningStats(const fs::path& workspace, const VtreeAsset& asset, const fs::path& asset_path) {
  PruningStats stats;
  const fs::path volume_json = workspace / "volume" / "volume.json";
  if (fs::exists(volume_json)) {
    const nlohmann::json doc = ParseJsonFile(volume_json);
    try {
      for (const nlohmann::json& level : doc.at("levels"))
        stats.levels.push_back({level.at("level").get<int>(), level.at("billboards_before_pruning").get<uint64_t>(),
                                level.at("billboards").get<uint64_t>(), level.at("pruned_percent").get<double>()});
    } catch (const nlohmann::json::exception& e) {
      Fail(volume_json.string(),
           ": field 'levels' (level, billboards_before_pruning, billboards, pruned_percent): ", e.what());
    }
    stats.source = "volume/volume.json";  // relative: the workspace may still be a staging folder
    return stats;
  }
  for (size_t l = 0; l < asset.levels.size(); ++l) {
    const VtreeLevel& level = asset.levels[l];
    const uint64_t before = level.billboards_before_pruning, kept = level.billboards.size();
    stats.levels.push_back(
        {int(l), before, kept, before ? 100.0 * double(before - std::min(before, kept)) / double(before) : 0.0});
  }
  stats.source = asset_path.string();
  return stats;
}

std::vector<PlotSeries> ReadSeriesFile(const fs::path& file, const std::vector<std::string>& x_keys,
                                       const std::vector<std::string>& y_keys, const std::string& default_series) {
  if (!fs::exists(file)) return {};
  const nlohmann::json doc = ParseJsonFile(file);
  const nlohmann::json& points = doc.is_object() && doc.contains("points") ? doc.at("points") : doc;
  if (!points.is_array()) Fail(file.string(), ": expected {\"points\": [...]} or an array of points");
  std::vector<PlotSeries> series;
  for (size_t i = 0; i < points.size(); ++i) {
    const nlohmann::json& point = points[i];
    const nlohmann::json* x = point.is_object() ? FirstNumber(point, x_keys) : nullptr;
    const nlohmann::json* y = point.is_object() ? FirstNumber(point, y_keys) : nullptr;
    if (!x || !y)
      Fail(file.string(), ": point ", i, " needs a number under one of '", x_keys.front(), "'... and '", y_keys.front(),
           "'...: ", point.dump());
    const std::string name = point.is_object() && point.contains("series") && point["series"].is_string()
                                 ? point["series"].get<std::string>()
                                 : default_series;
    auto it = std::find_if(series.begin(), series.end(), [&](const PlotSeries& s) { return s.title == name; });
    if (it == series.end()) it = series.insert(series.end(), PlotSeries{name, {}});
    it->points.emplace_back(x->get<double>(), y->get<double>());
  }
  for (PlotSeries& s : series) std::sort(s.points.begin(), s.points.end());
  return series;
}

}  // namespace voltree
