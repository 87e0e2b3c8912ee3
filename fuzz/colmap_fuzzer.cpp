// libFuzzer target for the COLMAP model readers (text and binary): any input must either load or
// throw voltree::Error; crashes, sanitizer reports, timeouts and absurd allocations are bugs.
//
// The readers take a folder, so each input is cut into the three files of a model and written
// to a private folder (under /dev/shm when it exists, to keep the file system out of the loop).
// Input layout: byte 0 chooses text (even) or binary (odd); bytes 1 and 2 choose where the rest
// is cut into cameras / images / points3D.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "capture/colmap_binary.h"
#include "core/error.h"

namespace {

namespace fs = std::filesystem;

fs::path FuzzFolder() {
  const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  const fs::path folder = base / ("voltree_colmap_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  return folder;
}

void WriteBytes(const fs::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  static const fs::path folder = FuzzFolder();
  const bool binary = (data[0] & 1) != 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 3, size - 3);
  const size_t first = rest.size() * data[1] / 255;
  const size_t second = std::max(first, rest.size() * data[2] / 255);
  const char* extension = binary ? ".bin" : ".txt";
  for (const char* stem : {"cameras", "images", "points3D"})
    for (const char* any : {".bin", ".txt"}) fs::remove(folder / (std::string(stem) + any));
  WriteBytes(folder / (std::string("cameras") + extension), rest.substr(0, first));
  WriteBytes(folder / (std::string("images") + extension), rest.substr(first, second - first));
  WriteBytes(folder / (std::string("points3D") + extension), rest.substr(second));
  try {
    const voltree::ColmapModel model = voltree::ReadColmapModel(folder);
    (void)model.Views();
  } catch (const voltree::Error&) {}
  return 0;
}
