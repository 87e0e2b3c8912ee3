#include "render/scene.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {

using Json = nlohmann::json;

// Validation of one JSON document; every message starts with the file and the field's path.
struct Checker {
  std::string file;

  template <typename... Args>
  [[noreturn]] void Wrong(const std::string& field, const Args&... args) const {
    Fail(file, ": ", field, " ", args...);
  }

  static std::string Joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  }

  void Object(const Json& j, const std::string& field) const {
    if (!j.is_object()) Wrong(field, "must be an object, got ", j.type_name());
  }

  void KnownKeys(const Json& j, const std::string& field, const std::vector<std::string>& allowed) const {
    for (const auto& [key, value] : j.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        Fail(file, ": unknown key ", field.empty() ? "" : field + ".", key, " (expected ", Joined(allowed), ")");
  }

  const Json& Required(const Json& j, const std::string& key, const std::string& field) const {
    if (!j.contains(key)) Fail(file, ": ", field.empty() ? "" : field + ": ", "missing required key ", key);
    return j.at(key);
  }

  double Number(const Json& j, const std::string& field) const {
    if (!j.is_number()) Wrong(field, "must be a number, got ", j.dump());
    const double value = j.get<double>();
    if (!std::isfinite(value)) Wrong(field, "must be finite, got ", j.dump());
    return value;
  }

  std::vector<double> Numbers(const Json& j, const std::string& field, size_t count) const {
    if (!j.is_array() || j.size() != count) Wrong(field, "must be an array of ", count, " numbers, got ", j.dump());
    std::vector<double> out;
    for (size_t i = 0; i < count; ++i) out.push_back(Number(j[i], Str(field, "[", i, "]")));
    return out;
  }

  std::array<uint8_t, 3> Colour(const Json& j, const std::string& field) const {
    std::array<uint8_t, 3> out{};
    if (!j.is_array() || j.size() != 3) Wrong(field, "must be [R, G, B] with integers 0..255, got ", j.dump());
    for (size_t i = 0; i < 3; ++i) {
      if (!j[i].is_number_integer() || j[i].get<int64_t>() < 0 || j[i].get<int64_t>() > 255)
        Wrong(Str(field, "[", i, "]"), "must be an integer 0..255, got ", j[i].dump());
      out[i] = uint8_t(j[i].get<int>());
    }
    return out;
  }
};

std::vector<SceneAssetRef> ParseAssets(const Checker& check, const Json& j, const std::filesystem::path& folder) {
  check.Object(j, "assets");
  if (j.empty()) check.Wrong("assets", "must name at least one asset");
  std::vector<SceneAssetRef> assets;
  for (const auto& [name, value] : j.items()) {  // nlohmann keeps object keys sorted
    const std::string field = "assets." + name;
    if (name.empty()) check.Wrong("assets", "has an empty asset name");
    if (!value.is_string() || value.get<std::string>().empty())
      check.Wrong(field, "must be a non-empty path to a .vtree file, got ", value.dump());
    const std::filesystem::path path = value.get<std::string>();
    assets.push_back({name, path.is_absolute() ? path : folder / path});
  }
  return assets;
}

SceneGround ParseGround(const Checker& check, const Json& j) {
  check.Object(j, "ground");
  check.KnownKeys(j, "ground", {"centre", "colour", "size"});
  SceneGround ground;
  const Json& size = check.Required(j, "size", "ground");
  if (size.is_array()) {
    const std::vector<double> xy = check.Numbers(size, "ground.size", 2);
    ground.size = Eigen::Vector2d(xy[0], xy[1]);
  } else {
    ground.size = Eigen::Vector2d::Constant(check.Number(size, "ground.size"));
  }
  if (!(ground.size.minCoeff() > 0)) check.Wrong("ground.size", "must be > 0, got ", size.dump());
  if (j.contains("centre")) {
    const std::vector<double> xy = check.Numbers(j["centre"], "ground.centre", 2);
    ground.centre = Eigen::Vector2d(xy[0], xy[1]);
  }
  if (j.contains("colour")) ground.colour = check.Colour(j["colour"], "ground.colour");
  return ground;
}

SceneMeshRef ParseMesh(const Checker& check, const std::string& name, const Json& j,
                       const std::filesystem::path& folder) {
  const std::string field = "meshes." + name;
  if (name.empty()) check.Wrong("meshes", "has an empty mesh name");
  SceneMeshRef mesh;
  mesh.name = name;
  const Json* tree = &j;
  if (j.is_object()) {
    check.KnownKeys(j, field, {"seed", "tree", "up"});
    tree = &check.Required(j, "tree", field);
    if (j.contains("up")) {
      mesh.up = j["up"].is_string() ? j["up"].get<std::string>() : "";
      if (mesh.up != "y" && mesh.up != "z") check.Wrong(field + ".up", "must be \"y\" or \"z\", got ", j["up"].dump());
    }
    if (j.contains("seed")) {
      if (!j["seed"].is_number_unsigned())
        check.Wrong(field + ".seed", "must be an integer >= 0, got ", j["seed"].dump());
      mesh.seed = j["seed"].get<uint64_t>();
    }
  }
  if (!tree->is_string() || tree->get<std::string>().empty())
    check.Wrong(j.is_object() ? field + ".tree" : field, "must be a preset name or a .gltf, .glb or .obj path, got ",
                tree->dump());
  mesh.tree = tree->get<std::string>();
  const std::filesystem::path path = mesh.tree;
  mesh.path = path.is_absolute() ? path : folder / path;
  return mesh;
}

std::vector<SceneMeshRef> ParseMeshes(const Checker& check, const Json& j, const std::filesystem::path& folder) {
  check.Object(j, "meshes");
  std::vector<SceneMeshRef> meshes;
  for (const auto& [name, value] : j.items()) meshes.push_back(ParseMesh(check, name, value, folder));
  return meshes;
}

// The index of the entry called `name`, or -1.
template <typename Ref>
int IndexOf(const std::vector<Ref>& refs, const std::string& name) {
  const auto found = std::find_if(refs.begin(), refs.end(), [&](const Ref& r) { return r.name == name; });
  return found == refs.end() ? -1 : int(found - refs.begin());
}

SceneInstance ParseInstance(const Checker& check, const Json& j, size_t index, const Scene& scene) {
  const std::string field = Str("instances[", index, "]");
  check.Object(j, field);
  check.KnownKeys(j, field, {"asset", "position", "rotation", "scale"});
  SceneInstance instance;
  const Json& asset = check.Required(j, "asset", field);
  if (!asset.is_string()) check.Wrong(field + ".asset", "must be an asset name, got ", asset.dump());
  instance.asset = IndexOf(scene.assets, asset.get<std::string>());
  instance.mesh = IndexOf(scene.meshes, asset.get<std::string>());
  if (instance.asset < 0 && instance.mesh < 0) {
    std::vector<std::string> names;
    for (const SceneAssetRef& a : scene.assets) names.push_back(a.name);
    for (const SceneMeshRef& m : scene.meshes)
      if (IndexOf(scene.assets, m.name) < 0) names.push_back(m.name);
    check.Wrong(field + ".asset", asset.dump(), " is not one of the ",
                scene.meshes.empty() ? "assets" : "assets or meshes", " (", Checker::Joined(names), ")");
  }
  const std::vector<double> p = check.Numbers(check.Required(j, "position", field), field + ".position", 3);
  // Far beyond any landscape, and where cameras and depth ranges computed from it overflow.
  constexpr double kLargest = 1e9;
  for (double coordinate : p)
    if (std::abs(coordinate) > kLargest)
      check.Wrong(field + ".position", "must lie within +-1e9 scene units, got ", j["position"].dump());
  instance.transform.translation = Eigen::Vector3d(p[0], p[1], p[2]);
  if (j.contains("rotation")) instance.transform.rotation_degrees = check.Number(j["rotation"], field + ".rotation");
  if (j.contains("scale")) {
    instance.transform.scale = check.Number(j["scale"], field + ".scale");
    if (!(instance.transform.scale > 0 && instance.transform.scale <= kLargest))
      check.Wrong(field + ".scale", "must be > 0 and at most 1e9, got ", j["scale"].dump());
  }
  return instance;
}

// Every instance has what will be drawn: a mesh (`meshes`) or an asset.
void CheckInstancesDrawable(const Scene& scene, bool meshes) {
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const SceneInstance& instance = scene.instances[i];
    if (meshes && instance.mesh < 0)
      Fail(scene.name, ": instances[", i, "].asset \"", scene.assets[instance.asset].name,
           "\" has no mesh: a mesh LOD method draws the trees named in meshes");
    if (!meshes && instance.asset < 0)
      Fail(scene.name, ": instances[", i, "].asset \"", scene.meshes[instance.mesh].name,
           "\" is a mesh without a .vtree asset: draw it with a mesh LOD method (render --lod mesh, points, "
           "ellipsoids or cook)");
  }
}

}  // namespace

bool IsSceneFile(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension == ".json";
}

Scene ParseScene(std::string_view text, const std::string& name, const std::filesystem::path& asset_folder) {
  const Checker check{name};
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& error) {
    Fail(name, ": not valid JSON: ", error.what());
  }
  if (!j.is_object()) Fail(name, ": a scene must be a JSON object, got ", j.type_name());
  check.KnownKeys(j, "", {"assets", "ground", "instances", "meshes"});
  Scene scene;
  scene.name = name;
  if (j.contains("meshes")) scene.meshes = ParseMeshes(check, j["meshes"], asset_folder);
  if (scene.meshes.empty() || j.contains("assets"))
    scene.assets = ParseAssets(check, check.Required(j, "assets", ""), asset_folder);
  if (j.contains("ground")) scene.ground = ParseGround(check, j["ground"]);
  const Json& instances = check.Required(j, "instances", "");
  if (!instances.is_array()) check.Wrong("instances", "must be an array, got ", instances.type_name());
  for (size_t i = 0; i < instances.size(); ++i) scene.instances.push_back(ParseInstance(check, instances[i], i, scene));
  return scene;
}

Scene LoadScene(const std::filesystem::path& file, const SceneLoadOptions& options) {
  if (!std::filesystem::is_regular_file(file)) Fail(file.string(), ": scene file not found");
  const std::filesystem::path folder = options.asset_folder.empty() ? file.parent_path() : options.asset_folder;
  Scene scene = ParseScene(ReadFile(file), file.string(), folder);
  CheckInstancesDrawable(scene, options.meshes);
  if (options.meshes) return scene;
  std::vector<std::string> missing;
  for (const SceneAssetRef& asset : scene.assets)
    if (!std::filesystem::is_regular_file(asset.path))
      missing.push_back(Str("assets.", asset.name, " (", asset.path.string(), ")"));
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    Fail(file.string(), ": asset file", missing.size() > 1 ? "s" : "", " not found: ", list,
         options.asset_folder.empty() ? " (build them with samples/scenes/make_assets.sh, or pass --assets DIR)" : "");
  }
  return scene;
}

std::vector<VtreeAsset> ReadSceneAssets(const Scene& scene) {
  std::vector<VtreeAsset> assets;
  for (const SceneAssetRef& ref : scene.assets) {
    try {
      assets.push_back(ReadAsset(ref.path));
    } catch (const Error& error) {
      Fail(scene.name, ": assets.", ref.name, ": ", error.what());
    }
  }
  return assets;
}

}  // namespace voltree
