#include "pipeline/scene_layout.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "core/vtree.h"
#include "render/scene.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

double ParseNumberField(const std::string& file, int line, const std::string& column, const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value))
    FailAt(file, line, column, " '", text, "' is not a number");
  return value;
}

// The widest horizontal extent of the assets' kept cells, so that neighbours on the grid do not
// overlap.
double WidestFootprint(const std::vector<fs::path>& assets) {
  double widest = 0;
  for (const fs::path& path : assets) {
    const VtreeAsset asset = ReadAsset(path);
    widest =
        std::max({widest, asset.bounds_max.x() - asset.bounds_min.x(), asset.bounds_max.y() - asset.bounds_min.y()});
  }
  return widest;
}

// Millimetres are enough for where a tree stands, and keep the file readable.
double Rounded(double value) { return std::round(value * 1000) / 1000; }

// As the sample scenes are written: one line per asset list, ground and instance.
std::string SceneText(const nlohmann::ordered_json& assets, const nlohmann::ordered_json& ground,
                      const nlohmann::ordered_json& instances) {
  std::string text =
      "{\n  \"assets\": " + assets.dump() + ",\n  \"ground\": " + ground.dump() + ",\n  \"instances\": [\n";
  for (size_t i = 0; i < instances.size(); ++i)
    text += "    " + instances[i].dump() + (i + 1 < instances.size() ? ",\n" : "\n");
  return text + "  ]\n}\n";
}

}  // namespace

void SceneLayoutOptions::Check() const {
  if (assets.empty()) Fail("scene: no assets given");
  if (output.empty()) Fail("scene: no output file given (-o SCENE.json)");
  if (output.extension() != ".json") Fail(output.string(), ": a scene file must end in .json");
  if (!(spacing >= 0) || !std::isfinite(spacing)) Fail("--spacing ", spacing, ": expected a number >= 0");
  std::map<std::string, fs::path> names;
  for (const fs::path& asset : assets) {
    if (!fs::is_regular_file(asset)) Fail(asset.string(), ": no such asset file");
    const auto [where, inserted] = names.emplace(AssetNameFromPath(asset), asset);
    if (!inserted)
      Fail(asset.string(), ": its name '", where->first, "' is the same as that of ", where->second.string(),
           "; rename one folder");
  }
  if (!positions.empty() && !fs::is_regular_file(positions)) Fail(positions.string(), ": no such positions file");
}

std::string AssetNameFromPath(const fs::path& asset) {
  if (asset.filename() == "tree.vtree") {
    const fs::path folder = fs::absolute(asset).lexically_normal().parent_path();
    if (!folder.filename().empty()) return folder.filename().string();
  }
  return asset.stem().string();
}

std::vector<ScenePlacement> ReadPositionsCsv(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) Fail(csv.string(), ": cannot be read");
  const std::string file = csv.string();
  std::map<std::string, int> columns;  // name -> index
  std::vector<ScenePlacement> placements;
  std::set<std::string> seen;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = SplitCsvLine(line);
    if (columns.empty()) {
      for (size_t i = 0; i < fields.size(); ++i) {
        const std::string name = Lower(fields[i]);
        if (name != "tree" && name != "x" && name != "y" && name != "rotation" && name != "scale")
          FailAt(file, line_number, "unknown column '", fields[i], "'; expected tree, x, y, rotation, scale");
        if (!columns.emplace(name, int(i)).second) FailAt(file, line_number, "column '", fields[i], "' twice");
      }
      for (const char* needed : {"tree", "x", "y"})
        if (!columns.count(needed))
          FailAt(file, line_number, "the header has no column '", needed,
                 "' (expected tree, x, y[, rotation][, scale])");
      continue;
    }
    if (fields.size() != columns.size())
      FailAt(file, line_number, fields.size(), " fields, but the header names ", columns.size());
    ScenePlacement placement;
    placement.tree = fields[columns.at("tree")];
    if (placement.tree.empty()) FailAt(file, line_number, "tree is empty");
    if (!seen.insert(placement.tree).second) FailAt(file, line_number, "tree '", placement.tree, "' has a row already");
    placement.x = ParseNumberField(file, line_number, "x", fields[columns.at("x")]);
    placement.y = ParseNumberField(file, line_number, "y", fields[columns.at("y")]);
    if (columns.count("rotation"))
      placement.rotation = ParseNumberField(file, line_number, "rotation", fields[columns.at("rotation")]);
    if (columns.count("scale")) {
      placement.scale = ParseNumberField(file, line_number, "scale", fields[columns.at("scale")]);
      if (placement.scale <= 0) FailAt(file, line_number, "scale ", placement.scale, " must be > 0");
    }
    placements.push_back(placement);
  }
  if (columns.empty()) Fail(file, ": empty; expected a header (tree, x, y[, rotation][, scale]) and a row per tree");
  return placements;
}

std::vector<ScenePlacement> GridPlacements(const std::vector<std::string>& trees, double spacing) {
  const int columns = std::max(1, int(std::ceil(std::sqrt(double(trees.size())))));
  const int rows = (int(trees.size()) + columns - 1) / columns;
  std::vector<ScenePlacement> placements;
  for (size_t i = 0; i < trees.size(); ++i) {
    ScenePlacement placement;
    placement.tree = trees[i];
    placement.x = (double(int(i) % columns) - 0.5 * (columns - 1)) * spacing;
    placement.y = (double(int(i) / columns) - 0.5 * (rows - 1)) * spacing;
    placements.push_back(placement);
  }
  return placements;
}

int WriteSceneLayout(const SceneLayoutOptions& options) {
  options.Check();
  CheckCanWrite(options.output, options.force);
  std::vector<std::string> trees;
  for (const fs::path& asset : options.assets) trees.push_back(AssetNameFromPath(asset));

  const double footprint = WidestFootprint(options.assets);
  const double spacing = options.spacing > 0 ? options.spacing : (footprint > 0 ? Rounded(1.25 * footprint) : 1.0);
  std::vector<ScenePlacement> placements;
  if (options.positions.empty()) {
    placements = GridPlacements(trees, spacing);
  } else {
    std::map<std::string, ScenePlacement> surveyed;
    for (const ScenePlacement& placement : ReadPositionsCsv(options.positions))
      surveyed.emplace(placement.tree, placement);
    for (const std::string& tree : trees) {
      const auto found = surveyed.find(tree);
      if (found == surveyed.end()) Fail(options.positions.string(), ": no row for tree '", tree, "'");
      placements.push_back(found->second);
    }
  }

  // The ground covers every tree with half a spacing to spare.
  double min_x = placements[0].x, max_x = min_x, min_y = placements[0].y, max_y = min_y;
  for (const ScenePlacement& p : placements) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  const fs::path folder = fs::absolute(options.output).parent_path();
  nlohmann::ordered_json assets = nlohmann::ordered_json::object();
  for (size_t i = 0; i < trees.size(); ++i)
    assets[trees[i]] = fs::absolute(options.assets[i]).lexically_normal().lexically_relative(folder).generic_string();
  const nlohmann::ordered_json ground = {{"size", {Rounded(max_x - min_x + spacing), Rounded(max_y - min_y + spacing)}},
                                         {"centre", {Rounded(0.5 * (min_x + max_x)), Rounded(0.5 * (min_y + max_y))}}};
  nlohmann::ordered_json instances = nlohmann::ordered_json::array();
  for (const ScenePlacement& p : placements)
    instances.push_back({{"asset", p.tree},
                         {"position", {Rounded(p.x), Rounded(p.y), 0}},
                         {"rotation", p.rotation},
                         {"scale", p.scale}});
  const std::string text = SceneText(assets, ground, instances);
  ParseScene(text, options.output.string(), folder);  // what we write, the renderer reads
  WriteFileAtomic(options.output, text);
  return int(placements.size());
}

}  // namespace voltree
