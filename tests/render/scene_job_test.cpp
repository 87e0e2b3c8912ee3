// `voltree render SCENE.json`: frames of a scene, --assets, and the --turntable video.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/tree_renderer_job.h"
#include "render/turntable.h"
#include "render/test_assets.h"

namespace voltree {
namespace {

using test::WhiteAsset;

namespace fs = std::filesystem;

struct SceneJobFolder {
  fs::path path = fs::temp_directory_path() / ("voltree_scene_job_" + std::to_string(::getpid()));
  SceneJobFolder() { fs::create_directories(path / "assets"); }
  ~SceneJobFolder() { fs::remove_all(path); }
};

constexpr const char* kScene = R"({
  "assets": {"cube": "cube.vtree"},
  "ground": {"size": 30, "colour": [0, 0, 255]},
  "instances": [{"asset": "cube", "position": [-4, 0, 0]}, {"asset": "cube", "position": [4, 0, 0], "scale": 2},
                {"asset": "cube", "position": [0, 5, 0], "rotation": 30}]
})";

TEST(SceneJob, OrbitOfAScene) {
  SceneJobFolder temp;
  WriteFileAtomic(temp.path / "scene.json", kScene);
  WriteAsset(temp.path / "assets" / "cube.vtree", WhiteAsset());
  RenderJobOptions options;
  options.asset = temp.path / "scene.json";
  options.orbit = 2;
  options.width = options.height = 64;
  options.output = temp.path / "frames";
  EXPECT_THROW(RunRenderJob(options, nullptr), Error);  // cube.vtree is not next to the scene
  options.asset_folder = temp.path / "assets";
  const RenderJobResult result = RunRenderJob(options, nullptr);
  ASSERT_EQ(result.frames.size(), 2u);
  EXPECT_EQ(result.mean_instances_drawn, 3);
  EXPECT_GT(result.gpu.Total(), 0u);
  const Image8 frame = ReadImage8(options.output / "frame_000.png");
  int white = 0, ground = 0;
  for (size_t i = 0; i < frame.pixels.size(); i += 4) {
    white += frame.pixels[i] > 240 && frame.pixels[i + 2] > 240 && frame.pixels[i + 3] == 255;
    ground += frame.pixels[i] < 10 && frame.pixels[i + 2] > 245 && frame.pixels[i + 3] == 255;
  }
  EXPECT_GT(white, 40);
  EXPECT_GT(ground, 400);
  const std::string json = ReadFile(options.output / "frames.json");
  EXPECT_NE(json.find("\"instances_drawn\": 3"), std::string::npos) << json;
}

TEST(SceneJob, TurntableVideo) {
  SceneJobFolder temp;
  WriteAsset(temp.path / "tree.vtree", WhiteAsset());
  RenderJobOptions options;
  options.asset = temp.path / "tree.vtree";
  options.orbit = 4;
  options.width = 63, options.height = 48;  // odd: padded to even for yuv420p
  options.turntable = temp.path / "turn.mp4";
  if (!FindOnPath("ffmpeg")) {
    EXPECT_THROW(RunRenderJob(options, nullptr), Error);
    GTEST_SKIP() << "ffmpeg is not installed";
  }
  RunRenderJob(options, nullptr);
  const std::string video = ReadFile(options.turntable);
  ASSERT_GT(video.size(), 100u);
  EXPECT_EQ(video.substr(4, 4), "ftyp");                // an MP4
  EXPECT_THROW(RunRenderJob(options, nullptr), Error);  // no overwrite without --force
  options.force = true;
  EXPECT_NO_THROW(RunRenderJob(options, nullptr));
  for (const auto& entry : fs::directory_iterator(temp.path))  // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  options.cameras = temp.path / "sparse";
  options.orbit = 0;
  EXPECT_THROW(options.Check(), Error);  // a turntable is an orbit
}

TEST(SceneJob, TurntableWithoutFfmpegSaysSo) {
  SceneJobFolder temp;
  WriteAsset(temp.path / "tree.vtree", WhiteAsset());
  RenderJobOptions options;
  options.asset = temp.path / "tree.vtree";
  options.orbit = 2;
  options.turntable = temp.path / "turn.mp4";
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", temp.path.c_str(), 1);
  std::string message;
  try {
    RunRenderJob(options, nullptr);
  } catch (const Error& error) {
    message = error.what();
  }
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_NE(message.find("needs ffmpeg"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(options.turntable));
}

}  // namespace
}  // namespace voltree
