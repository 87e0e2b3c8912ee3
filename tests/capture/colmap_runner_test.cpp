// Running the real colmap CLI as a child process.
#include "capture/colmap_runner.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

TEST(ColmapRunner, FindsColmapAndSaysHowToInstallWhenMissing) {
  EXPECT_TRUE(fs::exists(FindColmap()));
  try {
    FindExecutable("colmap", "/nonexistent:/also/not/here", "apt-get install colmap");
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("apt-get install colmap"), std::string::npos) << error.what();
  }
}

TEST(ColmapRunner, FailingStageShowsLogTailAndPath) {
  const fs::path folder = fs::path(::testing::TempDir()) / "voltree_colmap_runner";
  fs::remove_all(folder);
  const fs::path log = folder / "mapper.log";
  try {
    RunColmapStage(FindColmap(), "mapper",
                   {"--database_path", (folder / "missing.db").string(), "--image_path", "/nonexistent",
                    "--output_path", "/nonexistent"},
                   log);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("colmap mapper failed"), std::string::npos) << message;
    EXPECT_NE(message.find(log.string()), std::string::npos) << message;
    EXPECT_NE(message.find("  | "), std::string::npos) << message;  // the log's tail
  }
  EXPECT_FALSE(ReadFile(log).empty());
}

TEST(ColmapRunner, ChildExitCodesAndSignalsAreReported) {
  const fs::path folder = fs::path(::testing::TempDir()) / "voltree_colmap_runner_sh";
  const ChildResult ok = RunChild("/bin/sh", {"-c", "echo out; echo err >&2"}, folder / "ok.log");
  EXPECT_TRUE(ok.ok());
  EXPECT_EQ(ReadFile(folder / "ok.log"), "out\nerr\n");
  EXPECT_EQ(RunChild("/bin/sh", {"-c", "exit 3"}, folder / "exit.log").exit_code, 3);
  EXPECT_EQ(RunChild("/bin/sh", {"-c", "kill -SEGV $$"}, folder / "crash.log").signal, 11);
  EXPECT_THROW(RunChild("/nonexistent/program", {}, folder / "none.log"), Error);
}

}  // namespace
}  // namespace voltree
