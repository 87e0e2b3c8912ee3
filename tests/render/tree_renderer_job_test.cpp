#include "render/tree_renderer_job.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "core/colmap_model.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/vtree.h"
#include "render/test_assets.h"

namespace voltree {
namespace {

using test::WhiteAsset;

namespace fs = std::filesystem;

struct RenderJobFolder {
  fs::path path = fs::temp_directory_path() / ("voltree_render_job_" + std::to_string(::getpid()));
  RenderJobFolder() { fs::create_directories(path); }
  ~RenderJobFolder() { fs::remove_all(path); }
};

TEST(RenderJob, ResizesCameras) {
  const Camera camera = Camera::Pinhole(200, 100, 150, 160, 100, 50);
  const Camera half = ResizeCamera(camera, 100, 50);
  EXPECT_DOUBLE_EQ(half.FocalX(), 75);
  EXPECT_DOUBLE_EQ(half.FocalY(), 80);
  EXPECT_DOUBLE_EQ(half.PrincipalPoint().x(), 50);
  Camera simple;
  simple.model = CameraModel::kSimplePinhole;
  simple.width = 200, simple.height = 100;
  simple.params = {150, 100, 50};
  EXPECT_THROW(ResizeCamera(simple, 100, 100), Error);  // aspect change with one focal length
}

TEST(RenderJob, OrbitWritesDeterministicFramesAndRefusesToOverwrite) {
  RenderJobFolder temp;
  WriteAsset(temp.path / "tree.vtree", WhiteAsset());
  RenderJobOptions options;
  options.asset = temp.path / "tree.vtree";
  options.orbit = 3;
  options.width = 64, options.height = 48;
  options.output = temp.path / "frames";
  const RenderJobResult result = RunRenderJob(options, nullptr);
  ASSERT_EQ(result.frames.size(), 3u);
  EXPECT_EQ(result.frames[0], "frame_000.png");
  const Image8 first = ReadImage8(options.output / "frame_000.png");
  EXPECT_EQ(first.width, 64);
  EXPECT_EQ(first.channels, 4);
  int opaque = 0;
  for (size_t i = 3; i < first.pixels.size(); i += 4) opaque += first.pixels[i] == 255;
  EXPECT_GT(opaque, 50);            // the tree is in the picture...
  EXPECT_EQ(first.at(0, 0, 3), 0);  // ...on a transparent background
  EXPECT_TRUE(fs::exists(options.output / "frames.json"));
  EXPECT_THROW(RunRenderJob(options, nullptr), Error);  // exists, no force
  const std::string bytes = ReadFile(options.output / "frame_001.png");
  const std::string json = ReadFile(options.output / "frames.json");
  options.force = true;
  RunRenderJob(options, nullptr);
  EXPECT_EQ(ReadFile(options.output / "frame_001.png"), bytes);  // deterministic, byte for byte
  EXPECT_EQ(ReadFile(options.output / "frames.json"), json);
}

// Progressive assets: --max-level caps the levels loaded (beyond the asset it clamps, and says so);
// a truncated file draws its whole levels and warns which are missing.
TEST(RenderJob, MaxLevelAndTruncatedAssetsSayWhatIsDrawn) {
  RenderJobFolder temp;
  const std::string bytes = SerializeAsset(WhiteAsset());  // levels 0..1
  WriteFileAtomic(temp.path / "tree.vtree", bytes);
  RenderJobOptions options;
  options.asset = temp.path / "tree.vtree";
  options.orbit = 1;
  options.width = 32, options.height = 32;
  options.output = temp.path / "frames";
  options.force = true;
  const std::string name = options.asset.string();
  options.max_level = 7;
  EXPECT_EQ(RunRenderJob(options, nullptr).notes, std::vector<std::string>{"note: --max-level 7 is beyond " + name +
                                                                           ", whose finest level is 1; clamped to 1"});
  options.max_level = 0;
  EXPECT_EQ(RunRenderJob(options, nullptr).notes,
            std::vector<std::string>{"note: --max-level 0: drawing levels 0..0 of " + name + "'s 0..1"});
  options.max_level = -1;
  EXPECT_TRUE(RunRenderJob(options, nullptr).notes.empty());
  // Cut inside level 1's billboards.
  WriteFileAtomic(options.asset, bytes.substr(0, bytes.size() - 3));
  const std::vector<std::string> notes = RunRenderJob(options, nullptr).notes;
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("warning: " + name +
                               " is truncated; drawing levels 0..0. levels 1..1 of 0..1 are missing: "
                               "the file ends at byte " +
                               std::to_string(bytes.size() - 3) + ", inside the BBRD chunk of level 1",
                           0),
            0u)
      << notes[0];
  options.max_level = -2;
  EXPECT_THROW(RunRenderJob(options, nullptr), OptionError);
}

TEST(RenderJob, CamerasFromAColmapModelNameTheFrames) {
  RenderJobFolder temp;
  WriteAsset(temp.path / "tree.vtree", WhiteAsset());
  ColmapModel model;
  model.cameras[1] = Camera::Pinhole(40, 30, 40, 40, 20, 15);
  ColmapImage image;
  image.image_id = 1;
  image.camera_id = 1;
  image.name = "held_007.jpg";
  image.pose = Pose::LookAt(Eigen::Vector3d(4, 1, 1.5), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ());
  model.images[1] = image;
  fs::create_directories(temp.path / "sparse");
  WriteColmapText(temp.path / "sparse", model);
  RenderJobOptions options;
  options.asset = temp.path / "tree.vtree";
  options.cameras = temp.path / "sparse";
  options.render.background = {0, 0, 1, 1};
  options.output = temp.path / "held";
  const RenderJobResult result = RunRenderJob(options, nullptr);
  ASSERT_EQ(result.frames.size(), 1u);
  const Image8 frame = ReadImage8(options.output / "held_007.png");
  EXPECT_EQ(frame.width, 40);
  EXPECT_EQ(frame.at(0, 0, 2), 255);  // opaque blue background
  EXPECT_EQ(frame.at(0, 0, 3), 255);
  options.orbit = 2;
  EXPECT_THROW(options.Check(), Error);  // both sources
}

}  // namespace
}  // namespace voltree
