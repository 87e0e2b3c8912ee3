#include "capture/photo_folder.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "core/error.h"
#include "core/image.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

bool IsPhotoFile(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* known : kPhotoExtensions)
    if (extension == known) return true;
  return false;
}

}  // namespace

std::vector<fs::path> FindPhotos(const fs::path& folder) {
  std::vector<fs::path> photos;
  std::error_code error;
  if (!fs::is_directory(folder, error)) return photos;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && IsPhotoFile(entry.path()) && entry.path().filename().string()[0] != '.')
      photos.push_back(entry.path());
  std::sort(photos.begin(), photos.end());
  return photos;
}

std::vector<fs::path> ListPhotos(const fs::path& folder) {
  if (!fs::is_directory(folder)) Fail(folder.string(), ": no such folder; expected the photos of the workspace there");
  const std::vector<fs::path> photos = FindPhotos(folder);
  if (photos.empty())
    Fail(folder.string(), ": no photos (expected .png, .jpg, .jpeg, .tif, .tiff, .bmp or .exr files)");
  std::map<std::string, fs::path> by_stem;
  for (const fs::path& photo : photos) {
    const auto [it, inserted] = by_stem.emplace(photo.stem().string(), photo);
    if (!inserted)
      Fail(photo.string(), ": has the same name as ", it->second.string(), "; their mattes would collide in mattes/",
           photo.stem().string(), ".png");
  }
  return photos;
}

std::vector<std::string> PhotoNames(const std::vector<fs::path>& photos) {
  std::vector<std::string> names;
  for (const fs::path& photo : photos) names.push_back(photo.filename().string());
  return names;
}

// Photos of different sizes (thumbnails, another camera) cannot be one capture, though the camera
// may be turned (portrait and landscape); a photo too small to hold a tree gives a matte of noise.
std::vector<fs::path> CheckPhotoSizes(const std::vector<fs::path>& photos) {
  constexpr int kMinSide = 16;
  std::vector<fs::path> turned;
  if (photos.empty()) return turned;
  const auto first = ReadImageSize(photos.front());
  for (const fs::path& photo : photos) {
    const auto size = ReadImageSize(photo);
    if (size.first < kMinSide || size.second < kMinSide)
      Fail(photo.string(), ": photo is ", size.first, "x", size.second, "; expected at least ", kMinSide, "x", kMinSide,
           " pixels");
    if (size == first) continue;
    if (size.first == first.second && size.second == first.first) {
      turned.push_back(photo);
      continue;
    }
    Fail(photo.string(), ": photo is ", size.first, "x", size.second, " but ", photos.front().string(), " is ",
         first.first, "x", first.second,
         "; expected every photo of a capture to have the same size (or turned by 90 degrees): one camera, one size");
  }
  return turned;
}

}  // namespace voltree
