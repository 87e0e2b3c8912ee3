// COLMAP text models: exact round trip, errors with file:line, the rig-aware layout.
#include "core/colmap_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "core/error.h"
#include "core/files.h"
#include "temp_dir.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

using testing::FreshFolder;

ColmapModel ExampleModel() {
  ColmapModel model;
  model.cameras[1] = Camera{CameraModel::kPinhole, 640, 480, {512.25, 511.125, 320.5, 239.75}};
  model.cameras[3] = Camera{CameraModel::kOpenCV, 800, 600, {700.1, 701.3, 399.9, 300.2, -0.1, 0.01, 1e-4, -2e-4}};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int id : {2, 5, 9}) {
    ColmapImage image;
    image.image_id = id;
    image.camera_id = id == 9 ? 3 : 1;
    image.name = "view_00" + std::to_string(id) + ".png";
    image.pose.rotation = Eigen::Quaterniond(u(random), u(random), u(random), u(random)).normalized();
    image.pose.translation = {u(random) * 5, u(random) * 5, u(random) * 5};
    for (int k = 0; k < 4; ++k) {
      image.keypoints.emplace_back(u(random) * 300 + 320, u(random) * 200 + 240);
      image.point3d_ids.push_back(k < 2 ? 100 + k : -1);
    }
    model.images[id] = image;
  }
  model.images[5].keypoints.clear();  // an image without observations: empty POINTS2D line
  model.images[5].point3d_ids.clear();
  for (int k = 0; k < 2; ++k) {
    ColmapPoint point;
    point.point_id = 100 + k;
    point.position = {u(random), u(random), u(random) + 3};
    point.color = {uint8_t(10 + k), 200, 255};
    point.error = 0.25 + k;
    point.track = {{2, k}, {9, k}};
    model.points[point.point_id] = point;
  }
  return model;
}

void ExpectSameModel(const ColmapModel& a, const ColmapModel& b) {
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (const auto& [id, camera] : a.cameras) {
    const Camera& other = b.cameras.at(id);
    EXPECT_EQ(camera.model, other.model);
    EXPECT_EQ(camera.width, other.width);
    EXPECT_EQ(camera.height, other.height);
    EXPECT_EQ(camera.params, other.params);  // exact: %.17g round-trips doubles
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (const auto& [id, image] : a.images) {
    const ColmapImage& other = b.images.at(id);
    EXPECT_EQ(image.camera_id, other.camera_id);
    EXPECT_EQ(image.name, other.name);
    EXPECT_EQ(image.pose.rotation.coeffs(), other.pose.rotation.coeffs());
    EXPECT_EQ(image.pose.translation, other.pose.translation);
    EXPECT_EQ(image.keypoints, other.keypoints);
    EXPECT_EQ(image.point3d_ids, other.point3d_ids);
  }
  ASSERT_EQ(a.points.size(), b.points.size());
  for (const auto& [id, point] : a.points) {
    const ColmapPoint& other = b.points.at(id);
    EXPECT_EQ(point.position, other.position);
    EXPECT_EQ(point.color, other.color);
    EXPECT_EQ(point.error, other.error);
    EXPECT_EQ(point.track, other.track);
  }
}

TEST(ColmapText, WriteThenReadIsExact) {
  const fs::path folder = FreshFolder("roundtrip");
  const ColmapModel model = ExampleModel();
  WriteColmapText(folder, model);
  const ColmapModel read = ReadColmapText(folder);
  ExpectSameModel(model, read);
  // Writing what was read gives the same bytes.
  const fs::path again = FreshFolder("roundtrip_again");
  WriteColmapText(again, read);
  for (const char* file : {"cameras.txt", "images.txt", "points3D.txt"})
    EXPECT_EQ(ReadFile(folder / file), ReadFile(again / file)) << file;
  // COLMAP's header lines, so its own tools and other readers recognize the files.
  EXPECT_EQ(ReadFile(folder / "images.txt").rfind("# Image list with two lines of data per image:\n", 0), 0u);
  EXPECT_NE(ReadFile(folder / "cameras.txt").find("# Number of cameras: 2\n"), std::string::npos);
}

TEST(ColmapText, ViewsAreSortedByNameWithTheirCameras) {
  const ColmapModel model = ExampleModel();
  const std::vector<View> views = model.Views();
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[0].name, "view_002.png");
  EXPECT_EQ(views[2].name, "view_009.png");
  EXPECT_EQ(views[2].camera.model, CameraModel::kOpenCV);
  EXPECT_EQ(views[1].pose.translation, model.images.at(5).pose.translation);
}

TEST(ColmapText, ReadsColmapDocumentationExample) {
  const fs::path folder = FreshFolder("docs");
  WriteFileAtomic(folder / "cameras.txt",
                  "# Camera list with one line of data per camera:\n"
                  "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
                  "# Number of cameras: 3\n"
                  "1 SIMPLE_PINHOLE 3072 2304 2559.81 1536 1152\n"
                  "2 PINHOLE 3072 2304 2560.56 2560.56 1536 1152\n"
                  "3 SIMPLE_RADIAL 3072 2304 2559.69 1536 1152 -0.0218531\r\n");
  WriteFileAtomic(folder / "images.txt",
                  "# Image list with two lines of data per image:\n"
                  "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
                  "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
                  "# Number of images: 2, mean observations per image: 2\n"
                  "1 0.851773 0.0165051 0.503764 -0.142941 -0.737434 1.02973 3.74354 1 P1180141.JPG\n"
                  "2362.39 248.498 58396 1784.7 268.254 59027 1784.7 268.254 -1\n"
                  "2 0.851773 0.0165051 0.503764 -0.142941 -0.737434 1.02973 3.74354 3 my photo.JPG\n"
                  "\n");
  // No points3D.txt: it is optional.
  const ColmapModel model = ReadColmapText(folder);
  EXPECT_EQ(model.cameras.size(), 3u);
  EXPECT_EQ(model.cameras.at(3).params.back(), -0.0218531);
  ASSERT_EQ(model.images.size(), 2u);
  EXPECT_EQ(model.images.at(1).keypoints.size(), 3u);
  EXPECT_EQ(model.images.at(1).point3d_ids[2], -1);
  EXPECT_EQ(model.images.at(2).name, "my photo.JPG");
  EXPECT_NEAR(model.images.at(1).pose.rotation.w(), 0.851773, 1e-5);  // normalized on read
  EXPECT_NEAR(model.images.at(1).pose.rotation.norm(), 1.0, 1e-15);
}

// Writes a model whose `file` is replaced by `contents`, and returns the reader's message.
std::string ReadError(const std::string& test, const std::string& file, const std::string& contents) {
  const fs::path folder = FreshFolder("bad_" + test);
  WriteColmapText(folder, ExampleModel());
  WriteFileAtomic(folder / file, contents);
  try {
    ReadColmapText(folder);
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

const char* kCameraHeader = "# Camera list\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n";
const char* kImageHeader = "# Image list\n#   IMAGE_ID, ...\n";

TEST(ColmapText, MalformedFilesNameFileAndLine) {
  struct Case {
    std::string name, file, contents, expected_location, expected_words;
  };
  const std::string cameras_ok = std::string(kCameraHeader) + "1 PINHOLE 640 480 500 500 320 240\n";
  const std::vector<Case> cases = {
      {"too_few_params", "cameras.txt", std::string(kCameraHeader) + "1 PINHOLE 640 480 500 500 320\n", "cameras.txt:3",
       "needs 8 fields"},
      {"not_a_number", "cameras.txt", std::string(kCameraHeader) + "1 PINHOLE 640 480 500 5OO 320 240\n",
       "cameras.txt:3", "PARAMS: expected a number, got '5OO'"},
      {"not_an_integer", "cameras.txt", std::string(kCameraHeader) + "1 PINHOLE 640.5 480 500 500 320 240\n",
       "cameras.txt:3", "WIDTH: expected an integer"},
      {"unknown_model", "cameras.txt", std::string(kCameraHeader) + "1 FISHEYE_9 640 480 500 500 320 240\n",
       "cameras.txt:3", "unknown camera model 'FISHEYE_9'"},
      {"negative_focal", "cameras.txt", std::string(kCameraHeader) + "1 PINHOLE 640 480 -500 500 320 240\n",
       "cameras.txt:3", "focal length must be positive"},
      {"duplicate_camera", "cameras.txt", cameras_ok + "1 PINHOLE 640 480 500 500 320 240\n", "cameras.txt:4",
       "duplicate CAMERA_ID 1"},
      {"missing_camera", "images.txt", std::string(kImageHeader) + "1 1 0 0 0 0 0 0 7 a.png\n\n", "images.txt:3",
       "CAMERA_ID 7 which is not in cameras.txt"},
      {"image_fields", "images.txt", std::string(kImageHeader) + "1 1 0 0 0 0 0 1 a.png\n\n", "images.txt:3",
       "got 9 fields"},
      {"image_number", "images.txt", std::string(kImageHeader) + "1 1 0 0 0 0 x 0 1 a.png\n\n", "images.txt:3",
       "TY: expected a number, got 'x'"},
      {"points2d_triplets", "images.txt", std::string(kImageHeader) + "1 1 0 0 0 0 0 0 1 a.png\n1 2 -1 4\n",
       "images.txt:4", "triplets"},
      {"zero_quaternion", "images.txt", std::string(kImageHeader) + "1 0 0 0 0 0 0 0 1 a.png\n\n", "images.txt:3",
       "quaternion"},
      {"duplicate_image", "images.txt",
       std::string(kImageHeader) + "1 1 0 0 0 0 0 0 1 a.png\n\n1 1 0 0 0 0 0 0 1 b.png\n\n", "images.txt:5",
       "duplicate IMAGE_ID 1"},
      {"point_fields", "points3D.txt", "# points\n100 0 0 0 1 2 3 0.5 2\n", "points3D.txt:2", "pairs"},
      {"point_colour", "points3D.txt", "# points\n100 0 0 0 1 256 3 0.5\n", "points3D.txt:2", "0..255"},
      {"point_track_image", "points3D.txt", "# points\n100 0 0 0 1 2 3 0.5 77 0\n", "points3D.txt:2", "IMAGE_ID 77"},
      {"infinite", "points3D.txt", "# points\n100 0 inf 0 1 2 3 0.5\n", "points3D.txt:2", "finite"},
  };
  for (const Case& c : cases) {
    const std::string message = ReadError(c.name, c.file, c.contents);
    EXPECT_NE(message.find(c.expected_location), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.expected_words), std::string::npos) << c.name << ": " << message;
  }
}

TEST(ColmapText, MissingFolderOrFileIsAnError) {
  const fs::path folder = FreshFolder("missing");
  try {
    ReadColmapText(folder);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("cameras.txt"), std::string::npos) << error.what();
  }
}

// COLMAP >= 3.12 writes rigs.txt and frames.txt; the image pose is sensor_from_rig * rig_from_world.
TEST(ColmapText, RigAwareLayoutTakesPosesFromFrames) {
  const fs::path folder = FreshFolder("rigs");
  WriteFileAtomic(folder / "cameras.txt", "1 PINHOLE 640 480 500 500 320 240\n2 PINHOLE 640 480 500 500 320 240\n");
  // images.txt poses are deliberately stale: the frames are authoritative.
  WriteFileAtomic(folder / "images.txt",
                  "1 1 0 0 0 9 9 9 1 left.png\n\n2 1 0 0 0 9 9 9 2 right.png\n\n3 1 0 0 0 9 9 9 1 left2.png\n\n");
  WriteFileAtomic(folder / "rigs.txt",
                  "# Rig calib list with one line of data per calib:\n"
                  "1 2 CAMERA 1 CAMERA 2 1 0 0 0 1 -0.5 0 0\n");
  WriteFileAtomic(folder / "frames.txt",
                  "# Frame list with one line of data per frame:\n"
                  "10 1 1 0 0 0 1 2 3 2 CAMERA 1 1 CAMERA 2 2\n"
                  "11 1 0.70710678118654757 0 0 0.70710678118654757 0 0 4 1 CAMERA 1 3\n");
  const ColmapModel model = ReadColmapText(folder);
  EXPECT_LT((model.images.at(1).pose.translation - Eigen::Vector3d(1, 2, 3)).norm(), 1e-15);
  EXPECT_NEAR(model.images.at(1).pose.rotation.w(), 1.0, 1e-15);
  // Camera 2: rotated 180 degrees about Z relative to the rig, offset -0.5 in x.
  // R_2 = Rz(180) * I; t_2 = Rz(180) * (1, 2, 3) + (-0.5, 0, 0) = (-1.5, -2, 3).
  EXPECT_LT((model.images.at(2).pose.translation - Eigen::Vector3d(-1.5, -2, 3)).norm(), 1e-12);
  EXPECT_LT(
      (model.images.at(2).pose.rotation.toRotationMatrix() - Eigen::Vector3d(-1, -1, 1).asDiagonal().toDenseMatrix())
          .norm(),
      1e-12);
  EXPECT_LT((model.images.at(3).pose.translation - Eigen::Vector3d(0, 0, 4)).norm(), 1e-15);

  // An image in no frame is an error naming images.txt and its line.
  WriteFileAtomic(folder / "frames.txt", "10 1 1 0 0 0 1 2 3 2 CAMERA 1 1 CAMERA 2 2\n");
  try {
    ReadColmapText(folder);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("images.txt:5"), std::string::npos) << error.what();
  }
  // A frame line with the wrong DATA_IDS count names frames.txt:1.
  WriteFileAtomic(folder / "frames.txt", "10 1 1 0 0 0 1 2 3 3 CAMERA 1 1 CAMERA 2 2\n");
  try {
    ReadColmapText(folder);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("frames.txt:1"), std::string::npos) << error.what();
  }
  // Writing gives the legacy layout and removes the rig files it would contradict.
  fs::remove(folder / "frames.txt");
  WriteColmapText(folder, ReadColmapText(folder));
  EXPECT_FALSE(fs::exists(folder / "rigs.txt"));
}

TEST(ColmapModel, CheckRejectsImageWithoutCamera) {
  ColmapModel model = ExampleModel();
  model.images.at(2).camera_id = 42;
  EXPECT_THROW(model.Check(), Error);
  EXPECT_THROW(model.Views(), Error);
  EXPECT_THROW(WriteColmapText(FreshFolder("unchecked"), model), Error);
}

}  // namespace
}  // namespace voltree
