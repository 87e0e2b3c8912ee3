// A fresh empty folder for a test, under the system temp folder, removed when the test ends.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace voltree::testing {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("voltree_test_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace voltree::testing
