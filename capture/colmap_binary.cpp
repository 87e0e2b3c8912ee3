// Layout from COLMAP's reconstruction_io (3.8): counts are uint64, ids uint32 (points uint64),
// model ids int32, sizes uint64, all reals double; image names are NUL-terminated.
#include "capture/colmap_binary.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/byte_reader.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// COLMAP's numeric model ids (colmap/sensor/models.h); only the ones voltree supports map to a model.
std::optional<CameraModel> ModelFromColmapId(int32_t id) {
  switch (id) {
    case 0:
      return CameraModel::kSimplePinhole;
    case 1:
      return CameraModel::kPinhole;
    case 2:
      return CameraModel::kSimpleRadial;
    case 3:
      return CameraModel::kRadial;
    case 4:
      return CameraModel::kOpenCV;
    default:
      return std::nullopt;
  }
}

// Names of all COLMAP models, to name unsupported ones helpfully.
const char* ColmapModelName(int32_t id) {
  static const char* const kNames[] = {"SIMPLE_PINHOLE",
                                       "PINHOLE",
                                       "SIMPLE_RADIAL",
                                       "RADIAL",
                                       "OPENCV",
                                       "OPENCV_FISHEYE",
                                       "FULL_OPENCV",
                                       "FOV",
                                       "SIMPLE_RADIAL_FISHEYE",
                                       "RADIAL_FISHEYE",
                                       "THIN_PRISM_FISHEYE"};
  return id >= 0 && id < 11 ? kNames[id] : "unknown";
}

double FiniteDouble(ByteReader& in, const char* what) {
  const size_t at = in.offset();
  const double value = in.F64(what);
  if (!std::isfinite(value)) in.FailAt(at, what, " is not a finite number");
  return value;
}

// A count of records of at least `record_size` bytes each; rejects counts the file cannot hold,
// so corrupt counts never turn into huge allocations.
uint64_t RecordCount(ByteReader& in, const char* what, size_t record_size) {
  const size_t at = in.offset();
  const uint64_t count = in.U64(what);
  if (record_size > 0 && count > in.remaining() / record_size)
    in.FailAt(at, what, " says ", count, " but only ", in.remaining(), " bytes follow");
  return count;
}

void ExpectEnd(const ByteReader& in) {
  if (in.remaining() != 0) in.FailAt(in.offset(), in.remaining(), " unexpected bytes after the last record");
}

void ReadCameras(const fs::path& path, ColmapModel* model) {
  const std::string bytes = ReadFile(path);
  ByteReader in(bytes, path.string());
  constexpr size_t kMinRecord = 4 + 4 + 8 + 8 + 3 * 8;
  const uint64_t count = RecordCount(in, "camera count", kMinRecord);
  for (uint64_t i = 0; i < count; ++i) {
    const size_t record = in.offset();
    const uint32_t id = in.U32("CAMERA_ID");
    const int32_t model_id = in.I32("MODEL_ID");
    const auto camera_model = ModelFromColmapId(model_id);
    if (!camera_model)
      in.FailAt(record, "camera ", id, " uses COLMAP model ", model_id, " (", ColmapModelName(model_id),
                "), expected SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL or OPENCV");
    Camera camera;
    camera.model = *camera_model;
    const uint64_t width = in.U64("WIDTH"), height = in.U64("HEIGHT");
    if (width > uint64_t(std::numeric_limits<int>::max()) || height > uint64_t(std::numeric_limits<int>::max()))
      in.FailAt(record, "camera ", id, " size ", width, "x", height, " is too large");
    camera.width = int(width);
    camera.height = int(height);
    for (int p = 0; p < CameraModelParamCount(camera.model); ++p) camera.params.push_back(FiniteDouble(in, "PARAMS"));
    try {
      camera.Check();
    } catch (const Error& error) {
      in.FailAt(record, "camera ", id, ": ", error.what());
    }
    if (id > uint32_t(std::numeric_limits<int>::max()) || !model->cameras.emplace(int(id), camera).second)
      in.FailAt(record, "duplicate or invalid CAMERA_ID ", id);
  }
  ExpectEnd(in);
}

void ReadImages(const fs::path& path, ColmapModel* model) {
  const std::string bytes = ReadFile(path);
  ByteReader in(bytes, path.string());
  constexpr size_t kMinRecord = 4 + 7 * 8 + 4 + 1 + 8;
  const uint64_t count = RecordCount(in, "image count", kMinRecord);
  constexpr uint64_t kInvalidPoint = std::numeric_limits<uint64_t>::max();
  for (uint64_t i = 0; i < count; ++i) {
    const size_t record = in.offset();
    ColmapImage image;
    const uint32_t id = in.U32("IMAGE_ID");
    if (id > uint32_t(std::numeric_limits<int>::max())) in.FailAt(record, "IMAGE_ID ", id, " is too large");
    image.image_id = int(id);
    Eigen::Quaterniond q;
    q.w() = FiniteDouble(in, "QW");
    q.x() = FiniteDouble(in, "QX");
    q.y() = FiniteDouble(in, "QY");
    q.z() = FiniteDouble(in, "QZ");
    if (!(q.squaredNorm() > 1e-20)) in.FailAt(record, "image ", id, ": quaternion is zero");
    if (std::abs(q.squaredNorm() - 1.0) > 1e-14) q.normalize();
    image.pose.rotation = q;
    for (int k = 0; k < 3; ++k) image.pose.translation[k] = FiniteDouble(in, "translation");
    const uint32_t camera_id = in.U32("CAMERA_ID");
    if (camera_id > uint32_t(std::numeric_limits<int>::max()) || !model->cameras.count(int(camera_id)))
      in.FailAt(record, "image ", id, " names CAMERA_ID ", camera_id, " which is not in cameras.bin");
    image.camera_id = int(camera_id);
    image.name = std::string(in.UntilNul("image name"));
    const uint64_t points = RecordCount(in, "POINTS2D count", 3 * 8);
    image.keypoints.reserve(points);
    image.point3d_ids.reserve(points);
    for (uint64_t p = 0; p < points; ++p) {
      const double x = FiniteDouble(in, "X"), y = FiniteDouble(in, "Y");
      image.keypoints.emplace_back(x, y);
      const size_t at = in.offset();
      const uint64_t point_id = in.U64("POINT3D_ID");
      if (point_id != kInvalidPoint && point_id > uint64_t(std::numeric_limits<int64_t>::max()))
        in.FailAt(at, "POINT3D_ID ", point_id, " is too large");
      image.point3d_ids.push_back(point_id == kInvalidPoint ? -1 : int64_t(point_id));
    }
    if (!model->images.emplace(image.image_id, std::move(image)).second) in.FailAt(record, "duplicate IMAGE_ID ", id);
  }
  ExpectEnd(in);
}

void ReadPoints(const fs::path& path, ColmapModel* model) {
  const std::string bytes = ReadFile(path);
  ByteReader in(bytes, path.string());
  constexpr size_t kMinRecord = 8 + 3 * 8 + 3 + 8 + 8;
  const uint64_t count = RecordCount(in, "point count", kMinRecord);
  for (uint64_t i = 0; i < count; ++i) {
    const size_t record = in.offset();
    ColmapPoint point;
    const uint64_t id = in.U64("POINT3D_ID");
    if (id > uint64_t(std::numeric_limits<int64_t>::max())) in.FailAt(record, "POINT3D_ID ", id, " is too large");
    point.point_id = int64_t(id);
    for (int k = 0; k < 3; ++k) point.position[k] = FiniteDouble(in, "XYZ");
    for (int k = 0; k < 3; ++k) point.color[k] = in.U8("RGB");
    point.error = FiniteDouble(in, "ERROR");
    const uint64_t track = RecordCount(in, "track length", 8);
    point.track.reserve(track);
    for (uint64_t t = 0; t < track; ++t) {
      const uint32_t image_id = in.U32("IMAGE_ID");
      const uint32_t index = in.U32("POINT2D_IDX");
      const auto image = image_id <= uint32_t(std::numeric_limits<int>::max()) ? model->images.find(int(image_id))
                                                                               : model->images.end();
      if (image == model->images.end())
        in.FailAt(record, "point ", id, ": track names IMAGE_ID ", image_id, " which is not in images.bin");
      const size_t keypoints = image->second.keypoints.size();
      if (keypoints > 0 && index >= keypoints)
        in.FailAt(record, "point ", id, ": POINT2D_IDX ", index, " out of range for image ", image_id);
      point.track.emplace_back(int(image_id), int(index));
    }
    if (!model->points.emplace(point.point_id, std::move(point)).second) in.FailAt(record, "duplicate POINT3D_ID ", id);
  }
  ExpectEnd(in);
}

}  // namespace

ColmapModel ReadColmapBinary(const fs::path& folder) {
  for (const char* required : {"cameras.bin", "images.bin"})
    if (!fs::is_regular_file(folder / required))
      Fail((folder / required).string(), ": missing (expected a COLMAP binary model)");
  ColmapModel model;
  ReadCameras(folder / "cameras.bin", &model);
  ReadImages(folder / "images.bin", &model);
  if (fs::exists(folder / "points3D.bin")) ReadPoints(folder / "points3D.bin", &model);
  return model;
}

bool HasColmapModel(const fs::path& folder) {
  return fs::is_regular_file(folder / "cameras.txt") || fs::is_regular_file(folder / "cameras.bin");
}

ColmapModel ReadColmapModel(const fs::path& folder) {
  if (fs::is_regular_file(folder / "cameras.txt")) return ReadColmapText(folder);
  if (fs::is_regular_file(folder / "cameras.bin")) return ReadColmapBinary(folder);
  Fail(folder.string(), ": no COLMAP model here (expected cameras.txt/images.txt or cameras.bin/images.bin)");
}

}  // namespace voltree
