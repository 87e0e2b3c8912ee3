// Ctrl-C and SIGTERM through the real binary: an interrupted command (synth, matte, render) leaves
// no staging folder (".X.partial-PID") and no output, the user's files byte-identical, and ends as
// the signal says; staging folders left by a process that was killed outright are removed by the
// next run.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <random>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "staging_leftovers.h"

extern char** environ;

namespace voltree {
namespace {
namespace fs = std::filesystem;

// Starts voltree in `cwd` with SIGINT and SIGTERM at their defaults (a shell's "&" would ignore
// SIGINT), output to log.txt; returns its pid.
pid_t SpawnVoltree(const std::string& arguments, const fs::path& cwd) {
  std::vector<std::string> words = {
      "/bin/sh", "-c", Str("cd '", cwd.string(), "' && exec '", VOLTREE_BINARY, "' ", arguments, " > log.txt 2>&1")};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults, empty;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigemptyset(&empty);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &empty);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, "/bin/sh", nullptr, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  return error == 0 ? pid : -1;
}

size_t FilesUnder(const fs::path& folder) {
  std::error_code error;
  size_t count = 0;
  for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    count += it->is_regular_file();
  return count;
}

// Waits until `folder` holds at least `files` files (the command is mid-way), at most 60 s;
// false when the process `pid` ended first.
bool WaitForFiles(const fs::path& folder, size_t files, pid_t pid) {
  for (int i = 0; i < 1200; ++i) {
    if (FilesUnder(folder) >= files) return true;
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

using testing::StagingLeftovers;

// Every file under `root` with its bytes: what the user had before the interrupted command.
std::map<std::string, std::string> Contents(const fs::path& root) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) contents[entry.path().lexically_relative(root).string()] = ReadFile(entry.path());
  return contents;
}

class Interrupt : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(VOLTREE_BINARY)) GTEST_SKIP() << VOLTREE_BINARY << " is not built (build the voltree target)";
    dir_ = fs::temp_directory_path() /
           Str("voltree_interrupt_", ::getpid(), "_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  // Runs `arguments`, sends `signal_number` once the staging folder of `staged` holds a file,
  // and checks that the process died of that signal and that nothing half-built is left.
  void InterruptMidway(const std::string& arguments, const fs::path& staged, int signal_number) {
    const pid_t pid = SpawnVoltree(arguments, dir_);
    ASSERT_GT(pid, 0);
    const fs::path staging = dir_ / staged.parent_path() / Str(".", staged.filename().string(), ".partial-", pid);
    const bool started = WaitForFiles(staging, 1, pid);
    ::kill(pid, signal_number);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(started) << "no file appeared in " << staging << "; log:\n" << ReadFile(dir_ / "log.txt");
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status << "; log:\n"
                                                                          << ReadFile(dir_ / "log.txt");
    EXPECT_TRUE(StagingLeftovers(dir_).empty()) << StagingLeftovers(dir_).front();
  }
  fs::path dir_;
};

TEST_F(Interrupt, CtrlCDuringSynthLeavesNothing) {
  InterruptMidway("synth --tree young-oak --views 24 --held-out 0 --size 192x192 -o out", "out", SIGINT);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(Interrupt, SigtermDuringMatteLeavesThePhotosAndNothingElse) {
  // Textured photos large enough that information-flow matting takes about a second each.
  std::mt19937 random(5);
  Image8 photo(384, 384, 3);
  for (int y = 0; y < 384; ++y)
    for (int x = 0; x < 384; ++x) {
      const bool tree =
          (x - 192) * (x - 192) + (y - 150) * (y - 150) < 110 * 110 || (std::abs(x - 192) < 15 && y > 150);
      for (int c = 0; c < 3; ++c)
        photo.at(x, y, c) = uint8_t((tree ? (c == 1 ? 110 : 50) : (c == 2 ? 230 : 170)) + random() % 40);
    }
  for (int i = 0; i < 8; ++i) WriteImage(dir_ / "ws" / "images" / Str("v", i, ".png"), photo);
  const auto photos = Contents(dir_ / "ws");
  InterruptMidway("matte ws --threads 1 --refine infoflow", "ws/mattes", SIGTERM);
  EXPECT_TRUE(Contents(dir_ / "ws") == photos) << "only the photos should remain, unchanged";
}

TEST_F(Interrupt, CtrlCDuringRenderLeavesTheAssetAndNothingElse) {
  const pid_t demo = SpawnVoltree(
      "demo --tree young-oak --views 4 --held-out 1 --size 32x32 --levels 3 --orbit 0 --no-eval --quiet -o ws", dir_);
  int status = 0;
  ::waitpid(demo, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadFile(dir_ / "log.txt");
  const auto workspace = Contents(dir_ / "ws");
  InterruptMidway("render ws/tree.vtree --orbit 2000 -o frames", "frames", SIGINT);
  EXPECT_FALSE(fs::exists(dir_ / "frames"));
  EXPECT_TRUE(Contents(dir_ / "ws") == workspace) << "the workspace changed";
}

TEST_F(Interrupt, StagingOfADeadProcessIsRemovedByTheNextRun) {
  // A process id that is surely gone: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  const fs::path stale = dir_ / Str(".out.partial-", child);
  WriteFileAtomic(stale / "images" / "half.png", "half a photo");
  const fs::path live = dir_ / Str(".out.partial-", ::getpid());  // a live process's: kept
  WriteFileAtomic(live / "x", "in use");
  const pid_t pid =
      SpawnVoltree("synth --tree young-oak --views 1 --rings 1 --held-out 0 --size 32x32 --quiet -o out", dir_);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadFile(dir_ / "log.txt");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live / "x"));
  EXPECT_TRUE(fs::exists(dir_ / "out"));
}

TEST_F(Interrupt, RunResumesWithTheStagesThatDidNotFinish) {
  auto run = [&](const std::string& arguments) {
    const pid_t pid = SpawnVoltree(arguments, dir_);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, ReadFile(dir_ / "log.txt"));
  };
  const std::string tiny = " --tree young-oak --views 4 --held-out 1 --size 32x32 --levels 3 --orbit 0 --no-eval";
  ASSERT_EQ(run("demo -o ws --quiet" + tiny).first, 0);
  const std::string options = " --levels 3 --orbit 2 --orbit-size 32";
  ASSERT_EQ(run("run ws --force --quiet" + options).first, 0);
  // As if the run had been interrupted while compressing: the asset was never moved into place.
  fs::remove(dir_ / "ws" / "tree.vtree");
  const auto [status, output] = run("run ws" + options);
  EXPECT_EQ(status, 0) << output;
  EXPECT_NE(output.find("[reconstruct] skipped: up to date"), std::string::npos) << output;
  EXPECT_NE(output.find("[compress] start"), std::string::npos) << output;
  EXPECT_NE(output.find("[orbit] start"), std::string::npos) << "its input changed: " << output;
  EXPECT_TRUE(fs::exists(dir_ / "ws" / "tree.vtree"));
  // Changed options redo that stage and those after it, replacing what run wrote ...
  const auto [changed, message] = run("run ws --codebook 64" + options);
  EXPECT_EQ(changed, 0) << message;
  EXPECT_NE(message.find("[reconstruct] skipped: up to date"), std::string::npos) << message;
  EXPECT_NE(message.find("[compress] start"), std::string::npos) << message;
  // ... but an asset the user changed is theirs: replacing it needs --force.
  WriteFileAtomic(dir_ / "ws" / "tree.vtree", "the user's own asset");
  const auto [refused, why] = run("run ws --codebook 32" + options);
  EXPECT_EQ(refused, 1) << why;
  EXPECT_NE(why.find("tree.vtree already exists"), std::string::npos) << why;
  EXPECT_EQ(ReadFile(dir_ / "ws" / "tree.vtree"), "the user's own asset");
}

}  // namespace
}  // namespace voltree
