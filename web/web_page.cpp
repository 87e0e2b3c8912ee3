#include "web/web_page.h"

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"
#include "core/vtree.h"
#include "render/scene.h"
#include "web/base64.h"
#include "web/page_files.h"

namespace voltree {
namespace {

using nlohmann::json;

json Vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

// What the page draws: one asset (placed as is, no ground) or a scene's instances and ground.
json PageData(const WebPageOptions& options, WebPageResult* result) {
  json data = {{"name", options.input.filename().string()},
               {"assets", json::array()},
               {"instances", json::array()},
               {"ground", nullptr}};
  auto add_asset = [&](const std::filesystem::path& path, const VtreeAsset& asset) {
    // Raw chunks: the page has no zstd decoder. The same format version, checked the same way.
    data["assets"].push_back({{"file", path.filename().string()}, {"base64", EncodeBase64(SerializeAsset(asset))}});
  };
  if (!IsSceneFile(options.input)) {
    add_asset(options.input, ReadAsset(options.input));
    data["single"] = true;
    data["instances"].push_back({{"asset", 0}, {"position", {0, 0, 0}}, {"rotation", 0}, {"scale", 1}});
  } else {
    const Scene scene = LoadScene(options.input, {options.asset_folder});  // names the missing assets
    const std::vector<VtreeAsset> assets = ReadSceneAssets(scene);
    for (size_t i = 0; i < assets.size(); ++i) add_asset(scene.assets[i].path, assets[i]);
    data["single"] = false;
    for (const SceneInstance& instance : scene.instances)
      data["instances"].push_back({{"asset", instance.asset},
                                   {"position", Vec(instance.transform.translation)},
                                   {"rotation", instance.transform.rotation_degrees},
                                   {"scale", instance.transform.scale}});
    if (scene.ground) {
      const SceneGround& ground = *scene.ground;
      data["ground"] = {{"centre", {ground.centre.x(), ground.centre.y()}},
                        {"size", {ground.size.x(), ground.size.y()}},
                        {"colour", {ground.colour[0], ground.colour[1], ground.colour[2]}}};
    }
  }
  result->assets = data["assets"].size();
  result->instances = data["instances"].size();
  return data;
}

}  // namespace

void WebPageOptions::Check() const {
  if (input.empty()) Fail("web: an asset (.vtree) or a scene (.json) is required");
  if (output.empty()) Fail("web: an output folder (-o DIR) is required");
  if (!std::filesystem::is_regular_file(input)) Fail(input.string(), ": file not found");
  if (!asset_folder.empty() && !IsSceneFile(input))
    Fail("web: --assets applies to a scene (.json), not to ", input.string());
}

WebPageResult WriteWebPage(const WebPageOptions& options) {
  options.Check();
  CheckCanWrite(options.output, options.force);  // refuse at once, before reading the assets
  WebPageResult result;
  const json data = PageData(options, &result);
  StagedDirectory staged(options.output, options.force);
  const std::string script =
      "// Written by voltree web: the scene and its .vtree assets (base64), read by voltree.js.\n"
      "var VOLTREE_DATA = " +
      data.dump() + ";\n";
  const std::pair<std::string, std::string_view> files[] = {
      {"index.html", PageFile("index.html")}, {"voltree.js", PageFile("voltree.js")}, {"data.js", script}};
  for (const auto& [name, bytes] : files) {
    WriteFileAtomic(staged.path() / name, bytes);
    result.files.push_back(name);
    result.bytes += bytes.size();
  }
  staged.Commit();
  return result;
}

}  // namespace voltree
