// Scenes of tree meshes drawn with a mesh LOD method per instance (render --lod METHOD): a real
// (llvmpipe) render of tiny scenes of synthetic trees.
#include "lod/mesh_scene_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/progress.h"
#include "lod/mesh_scene_job.h"
#include "lod/synthetic_branches.h"
#include "lod/synthetic_foliage.h"
#include "render/gl_context.h"

namespace voltree {
namespace {

// The synthetic branches with `leaves` leaf cards around their tips: bark and foliage.
TreeMesh LeafyTree(int leaves = 300) {
  TreeMesh mesh = test::SyntheticBranches(false);
  const TreeMesh foliage = test::SyntheticFoliage(leaves, 0.06f);
  const auto offset = static_cast<uint32_t>(mesh.vertices.size());
  for (MeshVertex v : foliage.vertices) {
    v.position = 0.6f * v.position + Eigen::Vector3f(-0.3f, -0.3f, 0.3f);
    mesh.vertices.push_back(v);
  }
  mesh.materials.push_back(foliage.materials[1]);
  MeshGroup cards{1, {}};
  for (uint32_t index : foliage.groups[1].indices) cards.indices.push_back(index + offset);
  mesh.groups.push_back(cards);
  return mesh;
}

// Trees named "leafy" (and "bare", bark only) standing along +y at the given distances from the
// camera of LookingNorth.
Scene Row(const std::vector<double>& distances, const std::string& bare_at = "") {
  std::string json = bare_at.empty() ? R"({"meshes": {"leafy": "leafy"}, "instances": [)"
                                     : R"({"meshes": {"leafy": "leafy", "bare": "bare"}, "instances": [)";
  for (size_t i = 0; i < distances.size(); ++i)
    json += Str(i ? "," : "", R"({"asset": ")", bare_at == std::to_string(i) ? "bare" : "leafy",
                R"(", "position": [0, )", distances[i], ", 0]}");
  return ParseScene(json + "]}", "row.json", "");
}

std::vector<TreeMesh> Meshes(const Scene& scene) {
  std::vector<TreeMesh> meshes;
  for (const SceneMeshRef& ref : scene.meshes)
    meshes.push_back(ref.name == "bare" ? test::SyntheticBranches(false) : LeafyTree());
  return meshes;
}

View LookingNorth(int size = 96) {
  View view;
  view.camera = Camera::Pinhole(size, size, 1.2 * size, 1.2 * size, 0.5 * size, 0.5 * size);
  view.pose = Pose::LookAt(Eigen::Vector3d(0, 0, 0.7), Eigen::Vector3d(0, 1, 0.7), Eigen::Vector3d::UnitZ());
  return view;
}

MeshLodOptions Options(MeshLodMethod method, uint64_t seed = 1) {
  MeshLodOptions options;
  options.method = method;
  options.seed = seed;
  options.full_pixels = 200;
  options.ellipsoids.max_clusters = 16;
  return options;
}

size_t Covered(const Image8& image) {
  size_t covered = 0;
  for (size_t p = 3; p < image.pixels.size(); p += 4) covered += image.pixels[p] > 0;
  return covered;
}

constexpr MeshLodMethod kMethods[] = {MeshLodMethod::kMesh, MeshLodMethod::kPoints, MeshLodMethod::kEllipsoids,
                                      MeshLodMethod::kCook, MeshLodMethod::kNeubert};

TEST(MeshLodLevels, CountsAndLambdasRoundUpToCachedLevels) {
  for (size_t wanted : {0, 1, 7, 100, 499, 500, 900}) {
    const size_t count = QuantisedCount(wanted, 500, 2);
    EXPECT_GE(count, std::min<size_t>(wanted, 500)) << wanted;
    EXPECT_LE(count, 500u);
    if (wanted > 0 && wanted < 500) {
      EXPECT_LT(double(count), 1.42 * double(wanted) + 1) << wanted;
    }
  }
  EXPECT_EQ(QuantisedCount(0, 500, 2), 0u);
  EXPECT_EQ(QuantisedCount(260, 500, 1), 500u);  // one step per octave: 500, 250, 125, ...
  EXPECT_EQ(QuantisedCount(250, 500, 1), 250u);
  for (double lambda : {1.0, 0.9, 0.5, 0.3, 0.01}) {
    const double q = QuantisedLambda(lambda, 2);
    EXPECT_GE(q, lambda);
    EXPECT_LT(q, lambda * std::sqrt(2.0) + 1e-12);
  }
  EXPECT_DOUBLE_EQ(QuantisedLambda(0.5, 1), 0.5);
  EXPECT_THROW(QuantisedLambda(0, 2), Error);
}

TEST(MeshSceneRenderer, ThreeInstancesRenderWithEveryMethod) {
  GlContext context;
  const Scene scene = Row({3, 6, 12});
  for (MeshLodMethod method : kMethods) {
    MeshSceneRenderer renderer(scene, Meshes(scene), Options(method));
    SceneFrameStats stats;
    const Image8 image = renderer.Render(LookingNorth(), {0, 0, 0, 0}, true, &stats);
    SCOPED_TRACE(MeshLodMethodName(method));
    EXPECT_EQ(image.width, 96);
    EXPECT_GT(Covered(image), 200u);
    ASSERT_TRUE(stats.mesh.has_value());
    EXPECT_EQ(stats.instances_drawn, 3u);
    EXPECT_EQ(stats.mesh->full_instances + stats.mesh->reduced_instances, 3u);
    EXPECT_GT(stats.mesh->Primitives(), 0u);
    if (method == MeshLodMethod::kMesh) {
      EXPECT_EQ(stats.mesh->full_instances, 3u);
    } else {
      EXPECT_GE(stats.mesh->reduced_instances, 1u);  // the far ones
    }
    EXPECT_EQ(stats.mesh->points > 0, method == MeshLodMethod::kPoints);
    EXPECT_EQ(stats.mesh->ellipsoids > 0, method == MeshLodMethod::kEllipsoids);
    EXPECT_TRUE(renderer.Notes().empty());
  }
}

TEST(MeshSceneRenderer, PrimitivesFallWithDistanceAndTheNearestIsTheFullMesh) {
  GlContext context;
  for (MeshLodMethod method : kMethods) {
    SCOPED_TRACE(MeshLodMethodName(method));
    std::vector<size_t> primitives;
    for (double distance : {0.6, 2.0, 5.0, 12.0}) {
      const Scene scene = Row({distance});
      MeshSceneRenderer renderer(scene, Meshes(scene), Options(method));
      SceneFrameStats stats;
      renderer.Render(LookingNorth(), {0, 0, 0, 0}, false, &stats);
      primitives.push_back(stats.mesh->Primitives());
      if (distance == 0.6) {
        EXPECT_EQ(stats.mesh->full_instances, 1u);  // near: the polygons
      }
    }
    // On this tiny mesh (1 188 triangles) 16 ellipsoids of 120 triangles cost more than the mesh:
    // the fall is checked from the switch on for them, from the nearest for the others.
    const size_t first = method == MeshLodMethod::kEllipsoids ? 1 : 0;
    for (size_t k = first + 1; k < primitives.size(); ++k) EXPECT_LE(primitives[k], primitives[k - 1]) << k;
    if (method == MeshLodMethod::kMesh) {
      EXPECT_EQ(primitives.back(), primitives.front());
    } else {
      EXPECT_LT(primitives.back(), primitives[first]);
    }
  }
}

TEST(MeshSceneRenderer, DeterministicWithASeed) {
  GlContext context;
  const Scene scene = Row({4, 8});
  for (MeshLodMethod method : {MeshLodMethod::kPoints, MeshLodMethod::kCook, MeshLodMethod::kEllipsoids}) {
    SCOPED_TRACE(MeshLodMethodName(method));
    const auto render = [&](uint64_t seed) {
      MeshSceneRenderer renderer(scene, Meshes(scene), Options(method, seed));
      return renderer.Render(LookingNorth(), {0.5f, 0.7f, 0.9f, 1}, false);
    };
    const Image8 first = render(3);
    EXPECT_EQ(render(3), first);
    if (method != MeshLodMethod::kEllipsoids) {
      EXPECT_NE(render(4), first);  // another order, other leaves
    }
  }
}

TEST(MeshSceneRenderer, AMeshWithoutLeavesIsNamedAndTheRestAreStillReduced) {
  GlContext context;
  const Scene scene = Row({10, 12}, /*bare_at=*/"0");
  for (MeshLodMethod method :
       {MeshLodMethod::kCook, MeshLodMethod::kNeubert, MeshLodMethod::kPoints, MeshLodMethod::kEllipsoids}) {
    SCOPED_TRACE(MeshLodMethodName(method));
    const bool prunes = method == MeshLodMethod::kCook || method == MeshLodMethod::kNeubert;
    MeshSceneRenderer renderer(scene, Meshes(scene), Options(method));
    const std::vector<std::string> notes = renderer.Notes();
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("meshes.bare: no separable leaves"), std::string::npos) << notes[0];
    const std::vector<MeshLodLevel> levels = renderer.Levels(LookingNorth());
    EXPECT_FALSE(levels[1].full);  // the leafy tree
    if (prunes) {
      EXPECT_NE(notes[0].find(Str(MeshLodMethodName(method), " needs leaves; drawn as the full mesh")),
                std::string::npos);
      EXPECT_TRUE(levels[0].full);
    } else {
      EXPECT_NE(notes[0].find("draws only the branch lines"), std::string::npos);
      EXPECT_FALSE(levels[0].full);
    }
    SceneFrameStats stats;
    EXPECT_GT(Covered(renderer.Render(LookingNorth(), {0, 0, 0, 0}, false, &stats)), 0u);
    EXPECT_EQ(stats.mesh->reduced_instances, prunes ? 1u : 2u);
  }
}

// Trees named "leafy" at the given (x, y) positions.
Scene At(const std::vector<Eigen::Vector2d>& positions) {
  std::string json = R"({"meshes": {"leafy": "leafy"}, "instances": [)";
  for (size_t i = 0; i < positions.size(); ++i)
    json += Str(i ? "," : "", R"({"asset": "leafy", "position": [)", positions[i].x(), ", ", positions[i].y(), ", 0]}");
  return ParseScene(json + "]}", "trees.json", "");
}

TEST(MeshSceneRenderer, NeubertPrunesTreesHiddenBehindOthersAndNotTreesInTheOpen) {
  GlContext context;
  // A near tree filling most of the frame, two behind it; then the same three side by side.
  const Scene behind = At({{0, 1.2}, {0, 4}, {0, 8}});
  const Scene open = At({{0, 1.2}, {-1.6, 4}, {3.2, 8}});
  for (const Scene* scene : {&behind, &open}) {
    const bool hidden = scene == &behind;
    SCOPED_TRACE(hidden ? "behind" : "open");
    MeshSceneRenderer cook(*scene, Meshes(*scene), Options(MeshLodMethod::kCook));
    MeshSceneRenderer neubert(*scene, Meshes(*scene), Options(MeshLodMethod::kNeubert));
    const std::vector<MeshLodLevel> unoccluded = cook.Levels(LookingNorth());
    SceneFrameStats stats;
    EXPECT_GT(Covered(neubert.Render(LookingNorth(), {0, 0, 0, 0}, false, &stats)), 200u);
    EXPECT_TRUE(neubert.LastFrameHadPrepass());  // a first frame tests against its own pre-pass
    const std::vector<InstanceOcclusion>& tests = neubert.LastOcclusion();
    ASSERT_EQ(tests.size(), 3u);
    EXPECT_EQ(stats.mesh->visibility_tested, 3u);
    EXPECT_GT(tests[0].smoothed, 0.9);  // nothing stands in front of the near tree
    EXPECT_EQ(tests[0].level.lambda, unoccluded[0].lambda);
    for (size_t i = 1; i < 3; ++i) {
      SCOPED_TRACE(i);
      EXPECT_GT(tests[i].measured.tested, 8);
      if (hidden) {
        EXPECT_LT(tests[i].smoothed, 0.5);
        EXPECT_LT(tests[i].level.lambda, unoccluded[i].lambda);
        EXPECT_TRUE(tests[i].level.occluded);
      } else {
        EXPECT_GT(tests[i].smoothed, 0.9);
        EXPECT_EQ(tests[i].level.lambda, unoccluded[i].lambda);
      }
    }
    EXPECT_EQ(stats.mesh->occluded_instances, hidden ? 2u : 0u);
    // The next frame tests against this one's depth, with no pre-pass.
    neubert.Render(LookingNorth(), {0, 0, 0, 0}, false, &stats);
    EXPECT_FALSE(neubert.LastFrameHadPrepass());
    EXPECT_EQ(stats.mesh->occluded_instances, hidden ? 2u : 0u);
  }
}

TEST(MeshSceneRenderer, NeubertIsDeterministicAndForgetsItsHistoryOnReset) {
  GlContext context;
  const Scene scene = At({{0, 1.2}, {0, 4}, {0, 8}});
  const auto frames = [&](int count) {
    MeshSceneRenderer renderer(scene, Meshes(scene), Options(MeshLodMethod::kNeubert));
    std::vector<Image8> images;
    for (int k = 0; k < count; ++k) images.push_back(renderer.Render(LookingNorth(), {0.5f, 0.7f, 0.9f, 1}, false));
    renderer.ResetOcclusionHistory();
    images.push_back(renderer.Render(LookingNorth(), {0.5f, 0.7f, 0.9f, 1}, false));
    EXPECT_TRUE(renderer.LastFrameHadPrepass());
    return images;
  };
  const std::vector<Image8> first = frames(2);
  EXPECT_EQ(frames(2), first);
  EXPECT_EQ(first[2], first[0]);  // after the reset, the first frame again
}

TEST(MeshSceneJob, MissingMeshesAreNamed) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "voltree_mesh_scene_test";
  std::filesystem::create_directories(folder);
  Progress quiet(true);
  std::vector<std::string> notes;
  const Scene missing = ParseScene(R"({"meshes": {"birch": "trees/birch.glb"}, "instances": [
      {"asset": "birch", "position": [0, 0, 0]}]})",
                                   "forest.json", folder);
  try {
    LoadSceneMeshes(missing, quiet, &notes);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("forest.json: meshes.birch: mesh file not found"), std::string::npos)
        << error.what();
  }
  const Scene unknown = ParseScene(R"({"meshes": {"elm": "elm"}, "instances": []})", "forest.json", folder);
  try {
    LoadSceneMeshes(unknown, quiet, &notes);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("forest.json: meshes.elm: "), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("unknown preset"), std::string::npos) << error.what();
  }
  // An instance naming a tree that is an asset only, drawn as meshes.
  std::ofstream(folder / "scene.json") << R"({"assets": {"oak": "oak.vtree"}, "meshes": {"pine": "pine"},
      "instances": [{"asset": "oak", "position": [0, 0, 0]}]})";
  try {
    LoadScene(folder / "scene.json", {.asset_folder = "", .meshes = true});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("instances[0].asset \"oak\" has no mesh"), std::string::npos)
        << error.what();
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace voltree
