#include "core/image_size_guard.h"

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace voltree {

int64_t DecodeBytes(int64_t width, int64_t height, int channels, int bytes_per_channel) {
  return 2 * width * height * channels * bytes_per_channel;
}

std::optional<std::string> ImageSizeProblem(int64_t width, int64_t height, int channels, int bytes_per_channel,
                                            std::optional<int64_t> available_bytes) {
  if (width <= 0 || height <= 0) return Str("declares ", width, "x", height, " pixels; expected a positive size");
  // Divide rather than multiply, so absurd declared sizes cannot overflow.
  if (width > kMaxImagePixels / height)
    return Str("declares ", width, "x", height, " pixels, more than the ", kMaxImagePixels,
               " (16384x16384) voltree decodes; is the file damaged or crafted?");
  const int64_t needed = DecodeBytes(width, height, channels, bytes_per_channel);
  if (available_bytes && needed > *available_bytes)
    return Str("declares ", width, "x", height, " pixels, which need ", needed >> 20, " MiB to decode, but only ",
               *available_bytes >> 20, " MiB of memory are available");
  return std::nullopt;
}

std::optional<int64_t> FreeMemoryBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key;
    int64_t kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

void CheckImageSizeBeforeDecoding(const std::filesystem::path& path, int64_t width, int64_t height, int channels,
                                  int bytes_per_channel) {
  if (auto problem = ImageSizeProblem(width, height, channels, bytes_per_channel, FreeMemoryBytes()))
    Fail(path.string(), ": ", *problem);
}

}  // namespace voltree
