// PhotographTree writes a complete workspace, deterministically.
#include "samples/studio.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "samples/studio_rig.h"
#include "studio_test_mesh.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

class StudioWorkspace : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("voltree_studio_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    options_.width = 96;
    options_.height = 96;
    options_.views = 4;
    options_.rings = 2;
    options_.held_out = 2;
    options_.seed = 7;
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path root_;
  StudioOptions options_;
  Progress quiet_{true};
};

TEST_F(StudioWorkspace, WritesEveryFileAndTheTrueCameras) {
  const TreeMesh mesh = testing::MakeToyTree();
  const fs::path workspace = root_ / "set";
  PhotographTree(mesh, options_, workspace, quiet_);
  for (const char* name : {"view_000.png", "view_003.png"})
    for (const char* folder : {"images", "mattes", "foreground"}) EXPECT_TRUE(fs::exists(workspace / folder / name));
  for (const char* folder : {"images", "mattes", "rgba"})
    EXPECT_TRUE(fs::exists(workspace / "truth" / folder / "held_001.png")) << folder;
  EXPECT_EQ(ReadImageSize(workspace / "images/view_000.png"), std::make_pair(96, 96));
  EXPECT_EQ(ReadImage8(workspace / "images/view_001.png").channels, 3);
  EXPECT_EQ(ReadImage8(workspace / "mattes/view_001.png").channels, 1);
  EXPECT_EQ(ReadImage8(workspace / "foreground/view_001.png").channels, 4);

  const ColmapModel model = ReadColmapText(workspace / "sparse");
  ASSERT_EQ(model.cameras.size(), 1u);
  ASSERT_EQ(model.images.size(), 4u);
  const auto [lo, hi] = mesh.Bounds();
  const StudioRig rig = MakeStudioRig(lo.cast<double>(), hi.cast<double>(), options_);
  const std::vector<View> views = model.Views();
  for (size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(views[i].name, rig.inputs[i].name);
    EXPECT_LT((views[i].pose.Center() - rig.inputs[i].pose.Center()).norm(), 1e-9);
    EXPECT_EQ(views[i].camera.params, rig.inputs[i].camera.params);
  }
  EXPECT_EQ(ReadColmapText(workspace / "truth/sparse").images.size(), 2u);

  const auto meta = nlohmann::json::parse(ReadFile(workspace / "truth/meta.json"));
  EXPECT_EQ(meta["views"], 4);
  EXPECT_EQ(meta["seed"], 7);
  EXPECT_EQ(meta["size"], nlohmann::json({96, 96}));
  EXPECT_EQ(meta["triangles"], mesh.TriangleCount());
  const auto scene = nlohmann::json::parse(ReadFile(workspace / "scene.json"));
  EXPECT_EQ(scene["source"], "studio");
  EXPECT_EQ(scene["frame"], "tree");
  EXPECT_FLOAT_EQ(scene["bounds_max"][2].get<float>(), hi.z());
  // Nothing but the workspace was left behind (no staging folders).
  EXPECT_EQ(std::distance(fs::directory_iterator(root_), fs::directory_iterator()), 1);
}

TEST_F(StudioWorkspace, SameSeedSameBytesOtherSeedOtherGround) {
  const TreeMesh mesh = testing::MakeToyTree();
  options_.views = 2;
  options_.held_out = 1;
  PhotographTree(mesh, options_, root_ / "a", quiet_);
  PhotographTree(mesh, options_, root_ / "b", quiet_);
  size_t compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root_ / "a")) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), root_ / "a");
    EXPECT_EQ(ReadFile(entry.path()), ReadFile(root_ / "b" / relative)) << relative;
    ++compared;
  }
  EXPECT_GE(compared, 2 * 3 + 3 + 6 + 2u);
  options_.seed = 8;
  PhotographTree(mesh, options_, root_ / "c", quiet_);
  EXPECT_NE(ReadFile(root_ / "a/images/view_000.png"), ReadFile(root_ / "c/images/view_000.png"));
}

TEST_F(StudioWorkspace, RefusesNonEmptyFolderWithoutForce) {
  const TreeMesh mesh = testing::MakeToyTree();
  options_.views = 1;
  options_.rings = 1;
  options_.held_out = 0;
  const fs::path workspace = root_ / "set";
  fs::create_directories(workspace);
  WriteFileAtomic(workspace / "keep.txt", "user data");
  EXPECT_THROW(PhotographTree(mesh, options_, workspace, quiet_), Error);
  EXPECT_EQ(ReadFile(workspace / "keep.txt"), "user data");
  PhotographTree(mesh, options_, workspace, quiet_, /*force=*/true);
  EXPECT_FALSE(fs::exists(workspace / "keep.txt"));
  EXPECT_TRUE(fs::exists(workspace / "images/view_000.png"));
}

}  // namespace
}  // namespace voltree
