// `voltree synth` through the real binary: bad input fails clearly and writes nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

struct RunResult {
  int status = -1;
  std::string output;  // stdout and stderr
};

RunResult RunVoltree(const std::string& arguments) {
  RunResult result;
  const std::string command = std::string(VOLTREE_BINARY) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) result.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class SynthCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("voltree_synth_cli_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  size_t EntriesInRoot() const { return std::distance(fs::directory_iterator(root_), fs::directory_iterator()); }
  fs::path root_;
};

TEST_F(SynthCommand, UnknownPresetListsThePresets) {
  const RunResult result = RunVoltree("synth --tree baobab -o " + (root_ / "out").string());
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("baobab"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("oak, pine, young-oak"), std::string::npos) << result.output;
  EXPECT_EQ(EntriesInRoot(), 0u) << "something was written";
}

TEST_F(SynthCommand, ExistingFolderNeedsForce) {
  const fs::path out = root_ / "out";
  fs::create_directories(out);
  WriteFileAtomic(out / "mine.txt", "keep");
  const RunResult result =
      RunVoltree("synth --tree young-oak --views 1 --rings 1 --held-out 0 --size 32x32 -o " + out.string());
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--force"), std::string::npos) << result.output;
  EXPECT_EQ(ReadFile(out / "mine.txt"), "keep");
  EXPECT_EQ(EntriesInRoot(), 1u);
}

TEST_F(SynthCommand, BadSizeAndMissingMeshFail) {
  RunResult result = RunVoltree("synth --size 12by5 -o " + (root_ / "out").string());
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("WIDTHxHEIGHT"), std::string::npos) << result.output;
  result = RunVoltree("synth --tree " + (root_ / "missing.glb").string() + " -o " + (root_ / "out").string());
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("missing.glb"), std::string::npos) << result.output;
  EXPECT_EQ(EntriesInRoot(), 0u);
}

TEST_F(SynthCommand, SmallRunWritesAWorkspace) {
  const fs::path out = root_ / "out";
  const RunResult result = RunVoltree(
      "synth --tree young-oak --views 2 --rings 1 --held-out 1 --size 48x40 "
      "--supersample 2 --quiet -o " +
      out.string());
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(result.output.empty()) << result.output;  // --quiet
  EXPECT_TRUE(fs::exists(out / "images/view_001.png"));
  EXPECT_TRUE(fs::exists(out / "truth/rgba/held_000.png"));
  EXPECT_TRUE(fs::exists(out / "sparse/images.txt"));
  EXPECT_TRUE(fs::exists(out / "scene.json"));
  EXPECT_TRUE(RunVoltree("synth --help").output.find("--supersample") != std::string::npos);
}

}  // namespace
}  // namespace voltree
