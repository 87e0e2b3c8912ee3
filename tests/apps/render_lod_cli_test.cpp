// `voltree render SCENE --lod METHOD` end to end on a scene of two tiny OBJ trees, one of them
// without leaves: every method writes its frames and counts, the leafless tree is named, and bad
// input (an unknown method, a method on an asset, a missing mesh) is named before anything is
// written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "core/files.h"
#include "pipeline/voltree_binary.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

// A pole (opaque "bark", Z up) and, with `leaves`, a 6 x 6 x 3 lattice of leaf cards around its top.
std::string PoleObj(bool leaves) {
  std::string obj =
      "mtllib pole.mtl\nv -0.04 0 0\nv 0.04 0 0\nv 0.04 0 1\nv -0.04 0 1\n"
      "v 0 -0.04 0\nv 0 0.04 0\nv 0 0.04 1\nv 0 -0.04 1\nusemtl bark\nf 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\n";
  if (!leaves) return obj;
  std::string faces = "usemtl leaves\n";
  int base = 9;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 3; ++k, base += 4) {
        const double x = -0.4 + 0.15 * i, y = -0.4 + 0.15 * j + 0.02 * k, z = 0.7 + 0.15 * k, side = 0.07;
        obj += Str("v ", x, " ", y, " ", z, "\nv ", x + side, " ", y, " ", z, "\nv ", x + side, " ", y + 0.5 * side,
                   " ", z + side, "\nv ", x, " ", y + 0.5 * side, " ", z + side, "\n");
        faces += Str("f ", base, " ", base + 1, " ", base + 2, "\nf ", base, " ", base + 2, " ", base + 3, "\n");
      }
  return obj + faces;
}

class RenderLodCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / Str("voltree_render_lod_", ::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "trees");
    WriteFileAtomic(dir_ / "trees" / "leafy.obj", PoleObj(true));
    WriteFileAtomic(dir_ / "trees" / "bare.obj", PoleObj(false));
    WriteFileAtomic(dir_ / "trees" / "pole.mtl", "newmtl bark\nKd 0.4 0.3 0.2\nnewmtl leaves\nKd 0.2 0.6 0.2\n");
    WriteFileAtomic(dir_ / "scene.json", R"({
  "meshes": {"leafy": {"tree": "trees/leafy.obj", "up": "z"}, "bare": {"tree": "trees/bare.obj", "up": "z"}},
  "ground": {"size": 30},
  "instances": [
    {"asset": "leafy", "position": [0, 0, 0]},
    {"asset": "bare", "position": [3, 2, 0], "rotation": 40},
    {"asset": "leafy", "position": [-4, 6, 0], "scale": 1.3}
  ]
})");
  }
  void TearDown() override { fs::remove_all(dir_); }
  test::Outcome Run(const std::string& arguments) { return test::VoltreeCaptured(arguments, dir_.string()); }
  fs::path dir_;
};

TEST_F(RenderLodCli, EveryMethodWritesFramesWithTheirCountsAndNamesTheLeaflessTree) {
  for (const std::string method : {"mesh", "points", "ellipsoids", "cook", "neubert"}) {
    SCOPED_TRACE(method);
    const test::Outcome outcome =
        Run("render scene.json --lod " + method + " --orbit 2 --size 96x64 --stats --full-pixels 40 -o " + method);
    ASSERT_EQ(outcome.status, 0) << outcome.output;
    EXPECT_NE(outcome.output.find("per frame: "), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("instances per frame: 3.0 drawn"), std::string::npos) << outcome.output;
    if (method != "mesh") {
      EXPECT_NE(outcome.output.find("meshes.bare: no separable leaves"), std::string::npos) << outcome.output;
    }
    const auto frames = nlohmann::json::parse(ReadFile(dir_ / method / "frames.json"))["frames"];
    ASSERT_EQ(frames.size(), 2u);
    for (const auto& frame : frames) {
      EXPECT_GT(frame["triangles"].get<int>(), 0);
      EXPECT_EQ(frame["instances_full"].get<int>() + frame["instances_reduced"].get<int>(), 3);
      EXPECT_EQ(frame["points"].get<int>() > 0, method == "points");
      EXPECT_EQ(frame["ellipsoids"].get<int>() > 0, method == "ellipsoids");
      EXPECT_EQ(frame.contains("mean_visible"), method == "neubert");  // the occlusion test's f
    }
    if (method == "neubert") {
      EXPECT_NE(outcome.output.find("occlusion per frame: "), std::string::npos) << outcome.output;
    }
    EXPECT_TRUE(fs::is_regular_file(dir_ / method / "frame_001.png"));
  }
}

TEST_F(RenderLodCli, BadInputIsNamedAndNothingIsWritten) {
  test::Outcome outcome = Run("render scene.json --lod twigs --orbit 1 -o out");
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.output.find("--lod 'twigs': expected a rule for .vtree assets (screen, planes) or, for a scene's "
                                "meshes, a method (mesh, points, ellipsoids, cook, neubert)"),
            std::string::npos)
      << outcome.output;
  outcome = Run("render tree.vtree --lod points --orbit 1 -o out");
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.output.find("a mesh LOD method draws a scene (.json) of meshes, not tree.vtree"), std::string::npos)
      << outcome.output;
  // The scene's assets are drawn without --lod METHOD: a mesh-only tree cannot be.
  outcome = Run("render scene.json --orbit 1 -o out");
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.output.find("is a mesh without a .vtree asset"), std::string::npos) << outcome.output;
  fs::remove(dir_ / "trees" / "bare.obj");
  outcome = Run("render scene.json --lod cook --orbit 1 -o out");
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.output.find("scene.json: meshes.bare: mesh file not found: "), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

}  // namespace
}  // namespace voltree
