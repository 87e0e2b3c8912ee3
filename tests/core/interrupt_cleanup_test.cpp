// Staging folders of processes that are gone are removed; those of live processes are kept.
// (The signal path itself is tested through the binary: tests/apps/interrupt_cli_test.cpp.)
#include "core/interrupt_cleanup.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

TEST(InterruptCleanup, RemovesStagingOfDeadProcessesOnly) {
  const fs::path folder = fs::path(::testing::TempDir()) / "voltree_stale_staging";
  fs::remove_all(folder);
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);      // reaped: its id names no process now
  const pid_t parent = ::getppid();  // alive
  for (const char* tag : {"partial", "old", "tmp"}) WriteFileAtomic(folder / Str(".out.", tag, "-", child) / "f", "x");
  WriteFileAtomic(folder / Str(".out.partial-", parent) / "f", "x");
  WriteFileAtomic(folder / Str(".other.partial-", child) / "f", "x");  // another output's
  WriteFileAtomic(folder / ".out.partial-abc" / "f", "x");             // not a process id
  RemoveStaleStaging(folder / "out");
  EXPECT_FALSE(fs::exists(folder / Str(".out.partial-", child)));
  EXPECT_FALSE(fs::exists(folder / Str(".out.old-", child)));
  EXPECT_FALSE(fs::exists(folder / Str(".out.tmp-", child)));
  EXPECT_TRUE(fs::exists(folder / Str(".out.partial-", parent)));
  EXPECT_TRUE(fs::exists(folder / Str(".other.partial-", child)));
  EXPECT_TRUE(fs::exists(folder / ".out.partial-abc"));
  fs::remove_all(folder);
}

TEST(InterruptCleanup, RegisteringWithoutTheHandlerIsHarmless) {
  RemoveOnInterrupt("/nonexistent/.x.partial-1");
  ForgetOnInterrupt("/nonexistent/.x.partial-1");
  ForgetOnInterrupt("/never/registered");
}

}  // namespace
}  // namespace voltree
