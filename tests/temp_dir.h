// Fresh empty folders for tests, under the system temp folder.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
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

// A fresh empty folder named after the running test and `name`, left in place to inspect after a
// failure. The test's name keeps it apart from every other test, which ctest runs in parallel.
inline std::filesystem::path FreshFolder(const std::string& name) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string owner = test ? std::string(test->test_suite_name()) + "." + test->name() : "no_test";
  std::replace(owner.begin(), owner.end(), '/', '_');  // parameterised tests: Cases/Suite.Name/3
  const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / ("voltree_" + owner + "_" + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace voltree::testing
