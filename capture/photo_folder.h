// The photos of a capture workspace (DIR/images/): which files are photos, and whether they can be
// one capture. Matting and calibration both start here, so they agree on what a photo is.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

// The extensions of photo files (and of user mattes), lower case; matched in any case.
inline constexpr const char* kPhotoExtensions[] = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".bmp", ".exr"};

// The photo files in `folder` (PNG, JPEG, TIFF, BMP, EXR by extension, any case; not hidden),
// sorted by name. Nothing when the folder is missing or holds none: for counting.
std::vector<std::filesystem::path> FindPhotos(const std::filesystem::path& folder);

// FindPhotos, and the checks a capture needs: throws Error when the folder is missing, holds no
// photo, or two photos share a stem (their mattes would collide in mattes/).
std::vector<std::filesystem::path> ListPhotos(const std::filesystem::path& folder);

// File names only ("view_000.png"): how COLMAP names the photos.
std::vector<std::string> PhotoNames(const std::vector<std::filesystem::path>& photos);

// The photos that are turned by 90 degrees against the first (portrait among landscape). Throws
// Error naming the photo, both sizes and what was expected when a photo has another size
// (thumbnails, another camera) or is too small to hold a tree.
std::vector<std::filesystem::path> CheckPhotoSizes(const std::vector<std::filesystem::path>& photos);

}  // namespace voltree
