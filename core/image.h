// Interleaved images in memory and their file I/O through OpenImageIO.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace voltree {

template <typename T>
struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<T> pixels;  // row-major, top row first, channels interleaved

  Image() = default;
  Image(int w, int h, int c, T fill = T{}) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}

  bool empty() const { return pixels.empty(); }
  size_t Index(int x, int y, int c = 0) const { return (size_t(y) * width + x) * channels + c; }
  T& at(int x, int y, int c = 0) { return pixels[Index(x, y, c)]; }
  const T& at(int x, int y, int c = 0) const { return pixels[Index(x, y, c)]; }
  bool operator==(const Image&) const = default;
};

using Image8 = Image<uint8_t>;
using ImageF = Image<float>;

// Reads PNG, JPEG, TIFF, EXR, ... as 8-bit. `channels` > 0 converts: grey -> RGB replicates,
// RGB -> RGBA adds opaque alpha, RGBA -> grey keeps alpha when asked for 1 channel of a matte.
// Throws Error naming the file when it cannot be read. Pixels are turned upright as the EXIF
// "Orientation" attribute says (camera JPEGs shot in portrait).
Image8 ReadImage8(const std::filesystem::path& path, int channels = 0);
// Writes through a temporary file renamed into place, so a crash never leaves half an image.
// The format follows the extension. PNG output is deterministic (no timestamps).
void WriteImage(const std::filesystem::path& path, const Image8& image);
void WriteImage(const std::filesystem::path& path, const ImageF& image);  // EXR/TIFF float

// Width and height of an image file without decoding it, upright (as ReadImage8 returns it).
std::pair<int, int> ReadImageSize(const std::filesystem::path& path);

}  // namespace voltree
