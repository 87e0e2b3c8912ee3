// Scene JSON loader, frustum culling and back-to-front ordering (no GL needed).
#include "render/scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "core/error.h"
#include "core/files.h"
#include "render/frustum.h"
#include "render/scene_renderer.h"

namespace voltree {
namespace {

namespace fs = std::filesystem;

constexpr const char* kValid = R"({
  "assets": {"oak": "oak.vtree", "pine": "trees/pine.vtree", "young-oak": "/abs/young.vtree"},
  "ground": {"size": [40, 30], "centre": [1, 2], "colour": [10, 20, 30]},
  "instances": [
    {"asset": "oak", "position": [1, 2, 0], "rotation": 45, "scale": 1.5},
    {"asset": "pine", "position": [-3, 0, 0.5]},
    {"asset": "young-oak", "position": [0, 5, 0], "rotation": -10}
  ]
})";

// The message of the Error that parsing `json` throws ("" when it parses).
std::string ParseError(const std::string& json) {
  try {
    ParseScene(json, "scene.json", "/scenes");
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// kValid with `from` replaced by `to` (which must occur).
std::string Edited(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Scene, ParsesEveryField) {
  const Scene scene = ParseScene(kValid, "scene.json", "/scenes");
  ASSERT_EQ(scene.assets.size(), 3u);
  EXPECT_EQ(scene.assets[0].name, "oak");
  EXPECT_EQ(scene.assets[0].path, fs::path("/scenes/oak.vtree"));
  EXPECT_EQ(scene.assets[1].path, fs::path("/scenes/trees/pine.vtree"));
  EXPECT_EQ(scene.assets[2].path, fs::path("/abs/young.vtree"));
  ASSERT_EQ(scene.instances.size(), 3u);
  EXPECT_EQ(scene.instances[0].asset, 0);
  EXPECT_EQ(scene.instances[0].transform.translation, Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(scene.instances[0].transform.rotation_degrees, 45);
  EXPECT_EQ(scene.instances[0].transform.scale, 1.5);
  EXPECT_EQ(scene.instances[1].asset, 1);
  EXPECT_EQ(scene.instances[1].transform.scale, 1.0);  // defaults
  EXPECT_EQ(scene.instances[1].transform.rotation_degrees, 0.0);
  EXPECT_EQ(scene.instances[2].asset, 2);
  ASSERT_TRUE(scene.ground.has_value());
  EXPECT_EQ(scene.ground->size, Eigen::Vector2d(40, 30));
  EXPECT_EQ(scene.ground->centre, Eigen::Vector2d(1, 2));
  EXPECT_EQ(scene.ground->colour, (std::array<uint8_t, 3>{10, 20, 30}));
}

TEST(Scene, ErrorsNameTheFileAndTheField) {
  EXPECT_EQ(ParseError(kValid), "");
  EXPECT_EQ(ParseError(Edited(R"("asset": "pine")", R"("asset": "oka")")),
            R"(scene.json: instances[1].asset "oka" is not one of the assets (oak, pine, young-oak))");
  EXPECT_EQ(ParseError(Edited(R"("scale": 1.5)", R"("scale": -2)")),
            "scene.json: instances[0].scale must be > 0 and at most 1e9, got -2");
  EXPECT_EQ(ParseError(Edited(R"("position": [-3, 0, 0.5])", R"("position": [1e308, 0, 0.5])")),
            "scene.json: instances[1].position must lie within +-1e9 scene units, got [1e+308,0,0.5]");
  EXPECT_EQ(ParseError(Edited(R"("scale": 1.5)", R"("scael": 1.5)")),
            "scene.json: unknown key instances[0].scael (expected asset, position, rotation, scale)");
  EXPECT_EQ(ParseError(Edited(R"("ground")", R"("grund")")),
            "scene.json: unknown key grund (expected assets, ground, instances, meshes)");
  EXPECT_EQ(ParseError(Edited(R"("colour": [10, 20, 30])", R"("colour": [10, 256, 30])")),
            "scene.json: ground.colour[1] must be an integer 0..255, got 256");
  EXPECT_EQ(ParseError(Edited(R"("position": [-3, 0, 0.5])", R"("position": [-3, 0])")),
            "scene.json: instances[1].position must be an array of 3 numbers, got [-3,0]");
  EXPECT_EQ(ParseError(Edited(R"("rotation": -10)", R"("rotation": "10")")),
            R"(scene.json: instances[2].rotation must be a number, got "10")");
  EXPECT_EQ(ParseError(Edited(R"({"asset": "pine", "position": [-3, 0, 0.5]})", R"({"asset": "pine"})")),
            "scene.json: instances[1]: missing required key position");
  EXPECT_EQ(ParseError(Edited(R"("oak": "oak.vtree", )", R"("oak": 3, )")),
            "scene.json: assets.oak must be a non-empty path to a .vtree file, got 3");
  const std::string bad_json = ParseError(Edited(R"("scale": 1.5})", R"("scale": 1.5)"));
  EXPECT_EQ(bad_json.rfind("scene.json: not valid JSON: ", 0), 0u) << bad_json;
  EXPECT_EQ(ParseError("[]"), "scene.json: a scene must be a JSON object, got array");
}

TEST(Scene, LoadNamesMissingAssetFiles) {
  const fs::path dir = fs::temp_directory_path() / ("voltree_scene_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "override");
  WriteFileAtomic(dir / "scene.json", kValid);
  WriteFileAtomic(dir / "oak.vtree", "not read here");
  WriteFileAtomic(dir / "override" / "oak.vtree", "not read here");
  std::string message;
  try {
    LoadScene(dir / "scene.json");
  } catch (const Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find((dir / "scene.json").string() + ": asset files not found: assets.pine ("), std::string::npos)
      << message;
  EXPECT_NE(message.find("assets.young-oak (/abs/young.vtree)"), std::string::npos) << message;
  EXPECT_EQ(message.find("assets.oak"), std::string::npos) << message;  // that one exists
  // --assets DIR: relative paths resolve there instead.
  try {
    LoadScene(dir / "scene.json", {dir / "override"});
  } catch (const Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find((dir / "override" / "trees" / "pine.vtree").string()), std::string::npos) << message;
  EXPECT_THROW(LoadScene(dir / "missing.json"), Error);
  fs::remove_all(dir);
}

// The scene's meshes: trees named as a preset or a mesh file, for render --lod METHOD.
TEST(SceneMeshes, NameAPresetOrAMeshFileBesideOrInsteadOfTheAssets) {
  const Scene scene = ParseScene(R"({
    "assets": {"oak": "oak.vtree"},
    "meshes": {"oak": "oak", "aspen": {"tree": "trees/aspen.glb", "up": "z"}, "pine": {"tree": "pine", "seed": 5}},
    "instances": [{"asset": "oak", "position": [0, 0, 0]}, {"asset": "aspen", "position": [5, 0, 0]}]
  })",
                                 "scene.json", "/scenes");
  ASSERT_EQ(scene.meshes.size(), 3u);  // sorted by name
  EXPECT_EQ(scene.meshes[0].name, "aspen");
  EXPECT_EQ(scene.meshes[0].tree, "trees/aspen.glb");
  EXPECT_EQ(scene.meshes[0].path, std::filesystem::path("/scenes/trees/aspen.glb"));
  EXPECT_EQ(scene.meshes[0].up, "z");
  EXPECT_EQ(scene.meshes[2].seed, 5u);
  EXPECT_EQ(scene.meshes[1].up, "y");
  // One name, one tree: the oak is both an asset and a mesh; the aspen a mesh only.
  EXPECT_EQ(scene.instances[0].asset, 0);
  EXPECT_EQ(scene.instances[0].mesh, 1);
  EXPECT_EQ(scene.instances[1].asset, -1);
  EXPECT_EQ(scene.instances[1].mesh, 0);
  // Meshes alone make a scene.
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": "oak"}, "instances": []})"), "");
}

TEST(SceneMeshes, ErrorsNameTheField) {
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": "oak"}, "instances": [{"asset": "elm", "position": [0, 0, 0]}]})"),
            R"(scene.json: instances[0].asset "elm" is not one of the assets or meshes (oak))");
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": {"tree": "a.glb", "up": "x"}}, "instances": []})"),
            R"(scene.json: meshes.oak.up must be "y" or "z", got "x")");
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": 3}, "instances": []})"),
            "scene.json: meshes.oak must be a preset name or a .gltf, .glb or .obj path, got 3");
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": {"up": "y"}}, "instances": []})"),
            "scene.json: meshes.oak: missing required key tree");
  EXPECT_EQ(ParseError(R"({"meshes": {"oak": {"tree": "oak", "seed": -1}}, "instances": []})"),
            "scene.json: meshes.oak.seed must be an integer >= 0, got -1");
  EXPECT_EQ(ParseError(R"({"instances": []})"), "scene.json: missing required key assets");
}

TEST(SceneMeshes, AMeshOnlyTreeNeedsAMeshMethodToBeDrawn) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "voltree_scene_meshes_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.json") << R"({"meshes": {"pine": "pine"},
      "instances": [{"asset": "pine", "position": [0, 0, 0]}]})";
  try {
    LoadScene(dir / "scene.json");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("instances[0].asset \"pine\" is a mesh without a .vtree asset"),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(LoadScene(dir / "scene.json", {.asset_folder = "", .meshes = true}).instances.size(), 1u);
  std::filesystem::remove_all(dir);
}

View LookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, int width = 320, int height = 240) {
  View view;
  view.camera = Camera::Pinhole(width, height, 300, 300, 0.5 * width, 0.5 * height);
  view.pose = Pose::LookAt(eye, target, Eigen::Vector3d::UnitZ());
  return view;
}

TEST(Frustum, CullsBehindAndBesideKeepsInFront) {
  const View view = LookingAt(Eigen::Vector3d(0, -20, 2), Eigen::Vector3d(0, 0, 2));  // looking along +Y
  const Frustum frustum(view);
  EXPECT_TRUE(frustum.MayIntersect({Eigen::Vector3d(0, 0, 2), 1}));      // in front
  EXPECT_FALSE(frustum.MayIntersect({Eigen::Vector3d(0, -40, 2), 1}));   // behind
  EXPECT_TRUE(frustum.MayIntersect({Eigen::Vector3d(0, -20.5, 2), 1}));  // contains the eye
  // Half-width of the view at 20 m: 20 * 160 / 300 = 10.7 m.
  EXPECT_FALSE(frustum.MayIntersect({Eigen::Vector3d(13, 0, 2), 1}));   // beside
  EXPECT_TRUE(frustum.MayIntersect({Eigen::Vector3d(11.5, 0, 2), 1}));  // overlapping the edge
  // Randomized: a sphere is culled exactly when it is wholly behind the eye or outside a side
  // plane; spheres whose centre projects inside the image are never culled.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-60, 60), radius(0.1, 5);
  for (int i = 0; i < 2000; ++i) {
    const Sphere s{Eigen::Vector3d(coordinate(rng), coordinate(rng), coordinate(rng) / 4), radius(rng)};
    Eigen::Vector2d pixel;
    const bool projects_inside = view.WorldToPixel(s.centre, &pixel) && pixel.x() >= 0 && pixel.x() <= 320 &&
                                 pixel.y() >= 0 && pixel.y() <= 240 && view.pose.ToCamera(s.centre).z() > 0;
    const bool behind = view.pose.ToCamera(s.centre).z() < -s.radius;
    if (projects_inside) {
      EXPECT_TRUE(frustum.MayIntersect(s)) << i;
    }
    if (behind) {
      EXPECT_FALSE(frustum.MayIntersect(s)) << i;
    }
  }
}

// Random instances and cameras: the drawn order is back to front (distance non-increasing), it
// holds exactly the instances the frustum keeps, and an instance occluding another from the eye
// (nearer, on the same ray) is drawn after it.
TEST(SceneOrder, VisibleInstancesComeBackToFront) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-50, 50), angle(0, 6.283), unit(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Sphere> spheres;
    for (int i = 0; i < 60; ++i)
      spheres.push_back({Eigen::Vector3d(coordinate(rng), coordinate(rng), 5 * unit(rng)), 1 + 3 * unit(rng)});
    const Eigen::Vector3d eye(70 * std::cos(angle(rng)), 70 * std::sin(angle(rng)), 2 + 30 * unit(rng));
    const View view = LookingAt(eye, Eigen::Vector3d(coordinate(rng) / 3, coordinate(rng) / 3, 0));
    const std::vector<size_t> order = VisibleBackToFront(spheres, view);
    const Frustum frustum(view);
    size_t expected = 0;
    for (const Sphere& s : spheres) expected += frustum.MayIntersect(s);
    ASSERT_EQ(order.size(), expected);
    for (size_t k = 1; k < order.size(); ++k)
      ASSERT_GE((spheres[order[k - 1]].centre - eye).norm(), (spheres[order[k]].centre - eye).norm()) << trial;
    // All instances without culling, in the same relative order.
    const std::vector<size_t> all = VisibleBackToFront(spheres, view, false);
    ASSERT_EQ(all.size(), spheres.size());
    std::vector<size_t> filtered;
    for (size_t i : all)
      if (frustum.MayIntersect(spheres[i])) filtered.push_back(i);
    ASSERT_EQ(filtered, order);
  }
  // An occluder on the ray to another sphere is drawn last.
  const std::vector<Sphere> ray = {
      {Eigen::Vector3d(0, 5, 2), 1}, {Eigen::Vector3d(0, 30, 2), 1}, {Eigen::Vector3d(0, 15, 2), 1}};
  const std::vector<size_t> order =
      VisibleBackToFront(ray, LookingAt(Eigen::Vector3d(0, -10, 2), Eigen::Vector3d(0, 0, 2)));
  EXPECT_EQ(order, (std::vector<size_t>{1, 2, 0}));
}

TEST(SceneDepthRange, HoldsSpheresAndGround) {
  SceneGround ground;
  ground.size = Eigen::Vector2d(100, 100);
  const Eigen::Vector3d eye(0, -40, 10);
  const DepthRange range = SceneDepthRange(eye, {{Eigen::Vector3d(0, 0, 5), 5}}, ground);
  EXPECT_LE(range.near, 10.0 * 0.5 + 1e-9);  // the ground's nearest point is 10 m below
  EXPECT_GE(range.far, (Eigen::Vector3d(50, 50, 0) - eye).norm());
  EXPECT_NO_THROW(range.Check());
}

}  // namespace
}  // namespace voltree
