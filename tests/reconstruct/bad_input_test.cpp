// Bad inputs give a clear Error naming what is wrong, and nothing is written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/volume_io.h"
#include "reconstruct/reconstruct_workspace.h"
#include "synthetic_scene.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

ReconstructInput SmallInput() { return testing::PhantomInput(testing::BlobPhantom(8), 8, 32); }

std::string ErrorOf(const ReconstructInput& input, ReconstructOptions options = {}) {
  options.levels = 4;
  Progress quiet(true);
  try {
    Reconstruct(input, options, &quiet);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(BadInput, CamerasThatDoNotSeeTheBounds) {
  ReconstructInput input = SmallInput();
  input.bounds_min = Eigen::Vector3d(50, 50, 50);
  input.bounds_max = Eigen::Vector3d(51, 51, 51);
  const std::string error = ErrorOf(input);
  EXPECT_NE(error.find("view 'view_000.png' does not see the scene bounds"), std::string::npos) << error;
}

TEST(BadInput, BoundsSmallerThanAPixel) {
  ReconstructInput input = SmallInput();
  input.bounds_min = Eigen::Vector3d::Constant(1e-30);  // a user's scene.json: [1e-30]^3 .. [2e-30]^3
  input.bounds_max = Eigen::Vector3d::Constant(2e-30);
  const std::string error = ErrorOf(input);
  EXPECT_NE(error.find("smaller than one pixel in every view"), std::string::npos) << error;
  EXPECT_NE(error.find("scene.json"), std::string::npos) << error;
}

TEST(BadInput, AllZeroMattes) {
  ReconstructInput input = SmallInput();
  for (Image8& m : input.mattes) std::fill(m.pixels.begin(), m.pixels.end(), 0);
  const std::string error = ErrorOf(input);
  EXPECT_NE(error.find("nothing to reconstruct"), std::string::npos) << error;
}

TEST(BadInput, AllOneMattesLookInverted) {
  ReconstructInput input = SmallInput();
  for (Image8& m : input.mattes) std::fill(m.pixels.begin(), m.pixels.end(), 255);
  const std::string error = ErrorOf(input);
  EXPECT_NE(error.find("inverted or unmatted"), std::string::npos) << error;
}

TEST(BadInput, NanOrZeroFocalLength) {
  ReconstructInput input = SmallInput();
  input.views[3].camera.params[0] = std::nan("");
  std::string error = ErrorOf(input);
  EXPECT_NE(error.find("view 'view_003.png'"), std::string::npos) << error;
  EXPECT_NE(error.find("finite"), std::string::npos) << error;
  input = SmallInput();
  input.views[2].camera.params[1] = 0;
  error = ErrorOf(input);
  EXPECT_NE(error.find("view 'view_002.png'"), std::string::npos) << error;
  EXPECT_NE(error.find("focal length must be positive"), std::string::npos) << error;
}

TEST(BadInput, TooManyLevelsForMemory) {
  ReconstructOptions options;
  options.levels = 10;  // 512^3 at the finest level
  options.memory_limit_bytes = size_t(2) << 30;
  Progress quiet(true);
  std::string error;
  try {
    Reconstruct(SmallInput(), options, &quiet);
  } catch (const Error& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("10 levels at branching 2 (a 512^3 grid"), std::string::npos) << error;
  EXPECT_NE(error.find("only 2 GiB is available"), std::string::npos) << error;
}

// A workspace on disk with the given mattes.
void WriteWorkspace(const fs::path& dir, const ReconstructInput& input) {
  ColmapModel model;
  for (size_t v = 0; v < input.views.size(); ++v) {
    model.cameras[int(v) + 1] = input.views[v].camera;
    ColmapImage image;
    image.image_id = int(v) + 1;
    image.camera_id = int(v) + 1;
    image.name = input.views[v].name;
    image.pose = input.views[v].pose;
    model.images[image.image_id] = image;
    WriteImage(dir / "mattes" / input.views[v].name, input.mattes[v]);
    WriteImage(dir / "foreground" / input.views[v].name, input.foreground[v]);
  }
  fs::create_directories(dir / "sparse");
  WriteColmapText(dir / "sparse", model);
  WriteFileAtomic(
      dir / "scene.json",
      R"({"frame": "tree", "up": [0,0,1], "units": "metres", "bounds_min": [0,0,0], "bounds_max": [1,1,1], "source": "studio"})");
}

TEST(BadInput, WorkspaceWithEmptyMattesWritesNothing) {
  testing::TempDir dir("bad_workspace");
  ReconstructInput input = SmallInput();
  for (Image8& m : input.mattes) std::fill(m.pixels.begin(), m.pixels.end(), 0);
  WriteWorkspace(dir.path, input);
  ReconstructOptions options;
  options.levels = 4;
  Progress quiet(true);
  try {
    ReconstructWorkspace(dir.path, {options}, quiet);
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.path.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.path / "volume"));
  for (const auto& entry : fs::directory_iterator(dir.path))
    EXPECT_EQ(entry.path().filename().string().find("volume"), std::string::npos) << entry.path();
}

TEST(BadInput, MissingMatteNamesTheFile) {
  testing::TempDir dir("missing_matte");
  WriteWorkspace(dir.path, SmallInput());
  fs::remove(dir.path / "mattes" / "view_004.png");
  Progress quiet(true);
  try {
    ReconstructWorkspace(dir.path, {}, quiet);
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("mattes/view_004.png: missing matte"), std::string::npos) << e.what();
  }
}

TEST(Workspace, CommandLineWritesAReadableVolumeAndRespectsForce) {
  testing::TempDir dir("cli");
  WriteWorkspace(dir.path, SmallInput());
  const std::string command =
      std::string(VOLTREE_BINARY) + " reconstruct " + dir.path.string() + " --levels 4 --quiet --threads 2";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const Volume volume = ReadVolume(dir.path / "volume");
  EXPECT_EQ(volume.levels.size(), 4u);
  EXPECT_EQ(volume.views.size(), 8u);
  EXPECT_GT(volume.levels[3].billboards.size(), 0u);
  EXPECT_NE(std::system((command + " 2>/dev/null").c_str()), 0);  // exists: needs --force
  EXPECT_EQ(std::system((command + " --force").c_str()), 0);
  EXPECT_EQ(std::system((std::string(VOLTREE_BINARY) + " reconstruct --help | grep -q -- '--prune'").c_str()), 0);
}

}  // namespace
}  // namespace voltree
