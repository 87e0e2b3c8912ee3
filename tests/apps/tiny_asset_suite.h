// A test suite around one small studio asset (the oak, 8 photos at 96x96, 4 levels), built once
// per suite through the real binary in the suite's own temporary folder.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "pipeline/voltree_binary.h"

namespace voltree::test {

class TinyAssetSuite : public ::testing::Test {
 protected:
  // `prefix` names the folder ("voltree_web_" -> /tmp/voltree_web_PID).
  static void BuildTinyAsset(const std::string& prefix) {
    dir_ = std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    const std::string d = dir_.string();
    build_status_ = Voltree("synth --tree oak --views 8 --size 96x96 --quiet -o " + d + "/capture && " +
                            VOLTREE_BINARY + " reconstruct " + d + "/capture --levels 4 --quiet && " + VOLTREE_BINARY +
                            " compress " + d + "/capture --quiet");
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  // In SetUp: the suite's tests need the program `tool`, which scripts/setup.sh installs as `package`.
  static void RequireToolAndAsset(const std::string& tool, const std::string& package) {
    ASSERT_EQ(std::system(("command -v " + tool + " >/dev/null").c_str()), 0)
        << tool << " is not installed: run scripts/setup.sh, which installs Debian's " << package
        << " with the other packages";
    ASSERT_EQ(build_status_, 0) << "building the test asset failed";
  }
  static std::filesystem::path Dir() { return dir_; }
  static std::filesystem::path Asset() { return Dir() / "capture" / "tree.vtree"; }

 private:
  static inline std::filesystem::path dir_;
  static inline int build_status_ = -1;
};

}  // namespace voltree::test
