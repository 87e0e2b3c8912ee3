// COLMAP's binary sparse models (cameras.bin, images.bin, points3D.bin; little endian), and a
// loader that takes whichever of the text or binary form a folder holds.
#pragma once

#include <filesystem>

#include "core/colmap_model.h"

namespace voltree {

// Reads the three .bin files (points3D.bin optional). Every read is bounds-checked: a truncated
// or corrupt file throws Error naming the file and the byte offset. Camera models beyond those
// voltree supports (FISHEYE, FOV, ...) are an Error naming the model.
ColmapModel ReadColmapBinary(const std::filesystem::path& folder);

// Text when cameras.txt exists, else binary when cameras.bin exists, else an Error.
ColmapModel ReadColmapModel(const std::filesystem::path& folder);

// True when `folder` holds a COLMAP model in either form.
bool HasColmapModel(const std::filesystem::path& folder);

}  // namespace voltree
