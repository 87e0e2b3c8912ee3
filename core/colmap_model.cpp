// COLMAP text models: strict reader (every error names file:line and the field) and a writer that
// produces what COLMAP itself writes. Format: https://colmap.github.io/format.html; the rig-aware
// layout (rigs.txt, frames.txt) follows colmap/scene/reconstruction_io_text.cc (COLMAP >= 3.12).
#include "core/colmap_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// Lexing

// One physical line of a text file, split on blanks.
struct Line {
  int number = 0;         // 1-based, for messages
  std::string_view text;  // without the line break
  std::vector<std::string_view> tokens;
};

std::vector<std::string_view> SplitBlanks(std::string_view text) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

std::string_view TrimBlanks(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// All lines of a file (the text must outlive the lines).
std::vector<Line> SplitLines(std::string_view contents) {
  std::vector<Line> lines;
  size_t start = 0;
  int number = 1;
  while (start < contents.size()) {
    size_t end = contents.find('\n', start);
    if (end == std::string_view::npos) end = contents.size();
    std::string_view text = contents.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);  // files edited on Windows
    lines.push_back({number, text, SplitBlanks(text)});
    start = end + 1;
    ++number;
  }
  return lines;
}

bool IsSkipped(const Line& line) { return line.tokens.empty() || line.tokens.front().front() == '#'; }

// A text file being parsed: its name for messages and its lines.
class TextFile {
 public:
  explicit TextFile(const fs::path& path)
      : name_(path.string()), contents_(ReadFile(path)), lines_(SplitLines(contents_)) {}

  const std::string& name() const { return name_; }
  const std::vector<Line>& lines() const { return lines_; }

  [[noreturn]] void FailLine(const Line& line, const std::string& message) const {
    FailAt(name_, line.number, message);
  }

  template <typename T>
  T Integer(const Line& line, std::string_view token, std::string_view field) const {
    T value{};
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      FailLine(line, Str(field, ": expected an integer, got '", token, "'"));
    return value;
  }

  double Number(const Line& line, std::string_view token, std::string_view field) const {
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
      FailLine(line, Str(field, ": expected a number, got '", token, "'"));
    if (!std::isfinite(value)) FailLine(line, Str(field, ": expected a finite number, got '", token, "'"));
    return value;
  }

  // QW QX QY QZ TX TY TZ starting at tokens[first]: a world-to-camera (or sensor) transform.
  Pose ReadPose(const Line& line, size_t first) const {
    const auto& t = line.tokens;
    Eigen::Quaterniond q(Number(line, t[first], "QW"), Number(line, t[first + 1], "QX"),
                         Number(line, t[first + 2], "QY"), Number(line, t[first + 3], "QZ"));
    const double squared_norm = q.squaredNorm();
    if (!(squared_norm > 1e-20)) FailLine(line, "quaternion QW QX QY QZ is zero");
    // COLMAP writes unit quaternions with 17 digits; keep those bit-exact so that reading and
    // writing round-trips, and normalize hand-written ones.
    if (std::abs(squared_norm - 1.0) > 1e-14) q.normalize();
    Pose pose;
    pose.rotation = q;
    pose.translation = {Number(line, t[first + 4], "TX"), Number(line, t[first + 5], "TY"),
                        Number(line, t[first + 6], "TZ")};
    return pose;
  }

 private:
  std::string name_;
  std::string contents_;
  std::vector<Line> lines_;
};

// ---------------------------------------------------------------------------------------------
// cameras.txt, images.txt, points3D.txt

void ReadCameras(const TextFile& file, ColmapModel* model) {
  for (const Line& line : file.lines()) {
    if (IsSkipped(line)) continue;
    const auto& t = line.tokens;
    if (t.size() < 4)
      file.FailLine(line, Str("expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS[], got ", t.size(), " fields"));
    const int id = file.Integer<int>(line, t[0], "CAMERA_ID");
    Camera camera;
    try {
      camera.model = CameraModelFromName(t[1]);
    } catch (const Error& error) {
      file.FailLine(line, error.what());
    }
    const size_t expected = 4 + CameraModelParamCount(camera.model);
    if (t.size() != expected)
      file.FailLine(line, Str("camera model ", t[1], " needs ", expected, " fields (", expected - 4,
                              " parameters), got ", t.size()));
    camera.width = file.Integer<int>(line, t[2], "WIDTH");
    camera.height = file.Integer<int>(line, t[3], "HEIGHT");
    for (size_t i = 4; i < t.size(); ++i) camera.params.push_back(file.Number(line, t[i], "PARAMS"));
    try {
      camera.Check();
    } catch (const Error& error) {
      file.FailLine(line, error.what());
    }
    if (!model->cameras.emplace(id, std::move(camera)).second) file.FailLine(line, Str("duplicate CAMERA_ID ", id));
  }
}

// The second line of an image: X Y POINT3D_ID triplets, possibly empty.
void ReadPoints2D(const TextFile& file, const Line& line, ColmapImage* image) {
  const auto& t = line.tokens;
  if (t.size() % 3 != 0)
    file.FailLine(line, Str("POINTS2D: expected (X, Y, POINT3D_ID) triplets, got ", t.size(), " fields"));
  image->keypoints.reserve(t.size() / 3);
  image->point3d_ids.reserve(t.size() / 3);
  for (size_t i = 0; i < t.size(); i += 3) {
    image->keypoints.emplace_back(file.Number(line, t[i], "X"), file.Number(line, t[i + 1], "Y"));
    const int64_t point_id = file.Integer<int64_t>(line, t[i + 2], "POINT3D_ID");
    if (point_id < -1) file.FailLine(line, Str("POINT3D_ID must be -1 or an id, got ", point_id));
    image->point3d_ids.push_back(point_id);
  }
}

// Returns the line number of each image, for later messages.
std::map<int, int> ReadImages(const TextFile& file, ColmapModel* model) {
  std::map<int, int> line_of_image;
  std::set<std::string> names;
  const auto& lines = file.lines();
  for (size_t i = 0; i < lines.size(); ++i) {
    const Line& line = lines[i];
    if (IsSkipped(line)) continue;
    const auto& t = line.tokens;
    if (t.size() < 10)
      file.FailLine(line, Str("expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME, got ", t.size(), " fields"));
    ColmapImage image;
    image.image_id = file.Integer<int>(line, t[0], "IMAGE_ID");
    image.pose = file.ReadPose(line, 1);
    image.camera_id = file.Integer<int>(line, t[8], "CAMERA_ID");
    // The name is the rest of the line, so names with blanks survive.
    const size_t name_start = static_cast<size_t>(t[9].data() - line.text.data());
    image.name = std::string(TrimBlanks(line.text.substr(name_start)));
    if (!model->cameras.count(image.camera_id))
      file.FailLine(
          line, Str("image ", image.image_id, " names CAMERA_ID ", image.camera_id, " which is not in cameras.txt"));
    if (!names.insert(image.name).second) file.FailLine(line, Str("duplicate image NAME ", image.name));
    // The POINTS2D line follows directly (it may be empty, or missing at the end of the file).
    if (i + 1 < lines.size()) ReadPoints2D(file, lines[++i], &image);
    const int id = image.image_id;
    if (!model->images.emplace(id, std::move(image)).second) file.FailLine(line, Str("duplicate IMAGE_ID ", id));
    line_of_image[id] = line.number;
  }
  return line_of_image;
}

void ReadPoints(const TextFile& file, ColmapModel* model) {
  for (const Line& line : file.lines()) {
    if (IsSkipped(line)) continue;
    const auto& t = line.tokens;
    if (t.size() < 8 || (t.size() - 8) % 2 != 0)
      file.FailLine(line, Str("expected POINT3D_ID X Y Z R G B ERROR then (IMAGE_ID, POINT2D_IDX) pairs, got ",
                              t.size(), " fields"));
    ColmapPoint point;
    point.point_id = file.Integer<int64_t>(line, t[0], "POINT3D_ID");
    point.position = {file.Number(line, t[1], "X"), file.Number(line, t[2], "Y"), file.Number(line, t[3], "Z")};
    for (int c = 0; c < 3; ++c) {
      const int value = file.Integer<int>(line, t[4 + c], "RGB");
      if (value < 0 || value > 255) file.FailLine(line, Str("colour must be 0..255, got ", value));
      point.color[c] = static_cast<uint8_t>(value);
    }
    point.error = file.Number(line, t[7], "ERROR");
    for (size_t i = 8; i < t.size(); i += 2) {
      const int image_id = file.Integer<int>(line, t[i], "IMAGE_ID");
      const int index = file.Integer<int>(line, t[i + 1], "POINT2D_IDX");
      const auto image = model->images.find(image_id);
      if (image == model->images.end())
        file.FailLine(line, Str("track names IMAGE_ID ", image_id, " which is not in images.txt"));
      // Models stripped of their POINTS2D lines keep tracks; only check indices when we can.
      const int keypoint_count = static_cast<int>(image->second.keypoints.size());
      if (index < 0 || (keypoint_count > 0 && index >= keypoint_count))
        file.FailLine(line, Str("POINT2D_IDX ", index, " is out of range for image ", image_id, " (", keypoint_count,
                                " points)"));
      point.track.emplace_back(image_id, index);
    }
    const int64_t id = point.point_id;
    if (!model->points.emplace(id, std::move(point)).second) file.FailLine(line, Str("duplicate POINT3D_ID ", id));
  }
}

// ---------------------------------------------------------------------------------------------
// rigs.txt and frames.txt (COLMAP >= 3.12): an image's pose is sensor_from_rig * rig_from_world of
// the frame that contains it; images.txt then repeats it, but the frames are authoritative.

struct RigSensor {
  std::optional<Pose> sensor_from_rig;  // empty: unknown (not yet calibrated)
};

// rig id -> camera id -> sensor; the reference sensor has the identity pose.
using Rigs = std::map<int64_t, std::map<int, RigSensor>>;

Rigs ReadRigs(const TextFile& file) {
  Rigs rigs;
  for (const Line& line : file.lines()) {
    if (IsSkipped(line)) continue;
    const auto& t = line.tokens;
    if (t.size() < 2) file.FailLine(line, "expected RIG_ID NUM_SENSORS [REF_SENSOR_TYPE REF_SENSOR_ID SENSORS[]]");
    const int64_t rig_id = file.Integer<int64_t>(line, t[0], "RIG_ID");
    const int64_t sensor_count = file.Integer<int64_t>(line, t[1], "NUM_SENSORS");
    if (sensor_count < 0) file.FailLine(line, "NUM_SENSORS must not be negative");
    if (!rigs.emplace(rig_id, std::map<int, RigSensor>{}).second) file.FailLine(line, Str("duplicate RIG_ID ", rig_id));
    auto& sensors = rigs[rig_id];
    size_t at = 2;
    auto need = [&](size_t count) {
      if (at + count > t.size()) file.FailLine(line, Str("expected ", sensor_count, " sensors; the line ends early"));
    };
    for (int64_t s = 0; s < sensor_count; ++s) {
      need(2);
      const std::string_view type = t[at];
      const int sensor_id = file.Integer<int>(line, t[at + 1], "SENSOR_ID");
      at += 2;
      RigSensor sensor;
      if (s == 0) {
        sensor.sensor_from_rig = Pose{};  // the reference sensor defines the rig frame
      } else {
        need(1);
        const int has_pose = file.Integer<int>(line, t[at], "HAS_POSE");
        ++at;
        if (has_pose != 0 && has_pose != 1) file.FailLine(line, "HAS_POSE must be 0 or 1");
        if (has_pose) {
          need(7);
          sensor.sensor_from_rig = file.ReadPose(line, at);
          at += 7;
        }
      }
      if (type == "CAMERA") sensors[sensor_id] = sensor;  // other sensors (IMU) carry no images
    }
    if (at != t.size())
      file.FailLine(line, Str("expected ", at, " fields for ", sensor_count, " sensors, got ", t.size()));
  }
  return rigs;
}

struct FrameImage {
  int64_t rig_id = 0;
  Pose rig_from_world;
  int camera_id = 0;
  int line = 0;
};

// image id -> its frame.
std::map<int, FrameImage> ReadFrames(const TextFile& file) {
  std::map<int, FrameImage> frame_of_image;
  std::set<int64_t> frame_ids;
  for (const Line& line : file.lines()) {
    if (IsSkipped(line)) continue;
    const auto& t = line.tokens;
    if (t.size() < 10)
      file.FailLine(line, Str("expected FRAME_ID RIG_ID QW QX QY QZ TX TY TZ NUM_DATA_IDS DATA_IDS[], got ", t.size(),
                              " fields"));
    const int64_t frame_id = file.Integer<int64_t>(line, t[0], "FRAME_ID");
    if (!frame_ids.insert(frame_id).second) file.FailLine(line, Str("duplicate FRAME_ID ", frame_id));
    FrameImage frame;
    frame.rig_id = file.Integer<int64_t>(line, t[1], "RIG_ID");
    frame.rig_from_world = file.ReadPose(line, 2);
    frame.line = line.number;
    const int64_t data_count = file.Integer<int64_t>(line, t[9], "NUM_DATA_IDS");
    if (data_count < 0 || t.size() != 10 + 3 * static_cast<size_t>(data_count))
      file.FailLine(line, Str("NUM_DATA_IDS ", data_count, " needs ", 10 + 3 * std::max<int64_t>(data_count, 0),
                              " fields, got ", t.size()));
    for (size_t i = 10; i < t.size(); i += 3) {
      if (t[i] != "CAMERA") continue;  // IMU data have no image
      FrameImage entry = frame;
      entry.camera_id = file.Integer<int>(line, t[i + 1], "SENSOR_ID");
      const int image_id = file.Integer<int>(line, t[i + 2], "DATA_ID");
      if (!frame_of_image.emplace(image_id, entry).second)
        file.FailLine(line, Str("image ", image_id, " is in more than one frame"));
    }
  }
  return frame_of_image;
}

// Replaces each image's pose by the one its frame and rig give.
void ApplyFrames(const fs::path& folder, const std::map<int, int>& line_of_image, ColmapModel* model) {
  const TextFile frames_file(folder / "frames.txt");
  const std::map<int, FrameImage> frame_of_image = ReadFrames(frames_file);
  Rigs rigs;
  if (fs::exists(folder / "rigs.txt")) rigs = ReadRigs(TextFile(folder / "rigs.txt"));
  const std::string images_name = (folder / "images.txt").string();
  for (auto& [image_id, image] : model->images) {
    const auto frame = frame_of_image.find(image_id);
    if (frame == frame_of_image.end())
      FailAt(images_name, line_of_image.at(image_id), "image ", image_id, " is in no frame of ", frames_file.name());
    if (frame->second.camera_id != image.camera_id)
      FailAt(frames_file.name(), frame->second.line, "frame gives image ", image_id, " camera ",
             frame->second.camera_id, " but images.txt says ", image.camera_id);
    Pose sensor_from_rig;  // single-camera rigs (or no rigs.txt): identity
    if (const auto rig = rigs.find(frame->second.rig_id); rig != rigs.end()) {
      const auto sensor = rig->second.find(image.camera_id);
      if (sensor == rig->second.end())
        FailAt(frames_file.name(), frame->second.line, "camera ", image.camera_id, " is not a sensor of rig ",
               frame->second.rig_id);
      // Unknown sensor_from_rig: keep the pose images.txt states.
      if (!sensor->second.sensor_from_rig) continue;
      sensor_from_rig = *sensor->second.sensor_from_rig;
    } else if (!rigs.empty()) {
      FailAt(frames_file.name(), frame->second.line, "RIG_ID ", frame->second.rig_id, " is not in rigs.txt");
    }
    const Pose& rig_from_world = frame->second.rig_from_world;
    image.pose.rotation = sensor_from_rig.rotation * rig_from_world.rotation;
    image.pose.translation = sensor_from_rig.rotation * rig_from_world.translation + sensor_from_rig.translation;
  }
}

// ---------------------------------------------------------------------------------------------
// Writing

std::string Number17(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

std::string CamerasText(const ColmapModel& model) {
  std::string out =
      "# Camera list with one line of data per camera:\n"
      "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n";
  out += Str("# Number of cameras: ", model.cameras.size(), "\n");
  for (const auto& [id, camera] : model.cameras) {
    out += Str(id, " ", CameraModelName(camera.model), " ", camera.width, " ", camera.height);
    for (double p : camera.params) {
      out += ' ';
      out += Number17(p);
    }
    out += "\n";
  }
  return out;
}

std::string ImagesText(const ColmapModel& model) {
  size_t observations = 0;
  for (const auto& [id, image] : model.images)
    observations += std::count_if(image.point3d_ids.begin(), image.point3d_ids.end(), [](int64_t p) { return p >= 0; });
  const double mean = model.images.empty() ? 0.0 : double(observations) / double(model.images.size());
  std::string out =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n";
  out += Str("# Number of images: ", model.images.size(), ", mean observations per image: ", Number17(mean), "\n");
  for (const auto& [id, image] : model.images) {
    const Eigen::Quaterniond& q = image.pose.rotation;
    const Eigen::Vector3d& t = image.pose.translation;
    out +=
        Str(id, " ", Number17(q.w()), " ", Number17(q.x()), " ", Number17(q.y()), " ", Number17(q.z()), " ",
            Number17(t.x()), " ", Number17(t.y()), " ", Number17(t.z()), " ", image.camera_id, " ", image.name, "\n");
    for (size_t k = 0; k < image.keypoints.size(); ++k) {
      if (k > 0) out += " ";
      const int64_t point = k < image.point3d_ids.size() ? image.point3d_ids[k] : -1;
      out += Str(Number17(image.keypoints[k].x()), " ", Number17(image.keypoints[k].y()), " ", point);
    }
    out += "\n";
  }
  return out;
}

std::string PointsText(const ColmapModel& model) {
  const size_t track_total = ObservationCount(model);
  const double mean = model.points.empty() ? 0.0 : double(track_total) / double(model.points.size());
  std::string out =
      "# 3D point list with one line of data per point:\n"
      "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n";
  out += Str("# Number of points: ", model.points.size(), ", mean track length: ", Number17(mean), "\n");
  for (const auto& [id, point] : model.points) {
    out +=
        Str(id, " ", Number17(point.position.x()), " ", Number17(point.position.y()), " ", Number17(point.position.z()),
            " ", int(point.color[0]), " ", int(point.color[1]), " ", int(point.color[2]), " ", Number17(point.error));
    for (const auto& [image_id, index] : point.track) out += Str(" ", image_id, " ", index);
    out += "\n";
  }
  return out;
}

}  // namespace

std::vector<View> ColmapModel::Views() const {
  Check();
  std::vector<View> views;
  views.reserve(images.size());
  for (const auto& [id, image] : images) views.push_back({image.name, cameras.at(image.camera_id), image.pose});
  std::sort(views.begin(), views.end(), [](const View& a, const View& b) { return a.name < b.name; });
  return views;
}

void ColmapModel::Check() const {
  for (const auto& [id, camera] : cameras) {
    try {
      camera.Check();
    } catch (const Error& error) {
      Fail("camera ", id, ": ", error.what());
    }
  }
  for (const auto& [id, image] : images) {
    if (!cameras.count(image.camera_id))
      Fail("image ", id, " (", image.name, ") names camera ", image.camera_id, " which is not in the model");
    if (image.keypoints.size() != image.point3d_ids.size())
      Fail("image ", id, " (", image.name, ") has ", image.keypoints.size(), " keypoints but ",
           image.point3d_ids.size(), " point ids");
  }
}

ColmapModel ReadColmapText(const fs::path& folder) {
  for (const char* required : {"cameras.txt", "images.txt"})
    if (!fs::is_regular_file(folder / required))
      Fail((folder / required).string(),
           ": missing (expected a COLMAP text model: cameras.txt, images.txt, "
           "points3D.txt)");
  ColmapModel model;
  ReadCameras(TextFile(folder / "cameras.txt"), &model);
  const std::map<int, int> line_of_image = ReadImages(TextFile(folder / "images.txt"), &model);
  if (fs::exists(folder / "frames.txt")) ApplyFrames(folder, line_of_image, &model);
  if (fs::exists(folder / "points3D.txt")) ReadPoints(TextFile(folder / "points3D.txt"), &model);
  return model;
}

void WriteColmapText(const fs::path& folder, const ColmapModel& model) {
  model.Check();
  fs::create_directories(folder);
  WriteFileAtomic(folder / "cameras.txt", CamerasText(model));
  WriteFileAtomic(folder / "images.txt", ImagesText(model));
  WriteFileAtomic(folder / "points3D.txt", PointsText(model));
  // Stale rig files would override the poses just written when the folder is read again.
  for (const char* stale : {"rigs.txt", "frames.txt"}) {
    std::error_code ignored;
    fs::remove(folder / stale, ignored);
  }
}

size_t ObservationCount(const ColmapModel& model) {
  size_t count = 0;
  for (const auto& [id, point] : model.points) count += point.track.size();
  return count;
}

double MeanReprojectionError(const ColmapModel& model) {
  double total = 0;
  size_t count = 0;
  for (const auto& [id, point] : model.points)
    for (const auto& [image_id, index] : point.track) {
      const auto image = model.images.find(image_id);
      if (image == model.images.end() || index >= int(image->second.keypoints.size())) continue;
      const View view{image->second.name, model.cameras.at(image->second.camera_id), image->second.pose};
      Eigen::Vector2d pixel;
      if (!view.WorldToPixel(point.position, &pixel)) continue;
      total += (pixel - image->second.keypoints[index]).norm();
      ++count;
    }
  return count ? total / double(count) : 0.0;
}

}  // namespace voltree
