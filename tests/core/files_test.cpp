// Safe outputs: atomic files and staged folders.
#include "core/files.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "temp_dir.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

using testing::FreshFolder;

size_t EntryCount(const fs::path& folder) {
  return size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(Files, WriteFileAtomicReplacesAndLeavesNoTemporary) {
  const fs::path folder = FreshFolder("atomic");
  WriteFileAtomic(folder / "sub" / "a.txt", "first");
  WriteFileAtomic(folder / "sub" / "a.txt", std::string("second\0bytes", 12));
  EXPECT_EQ(ReadFile(folder / "sub" / "a.txt"), std::string("second\0bytes", 12));
  EXPECT_EQ(EntryCount(folder / "sub"), 1u);
  EXPECT_THROW(ReadFile(folder / "missing.txt"), Error);
}

TEST(Files, CheckCanWriteNeedsForceForExistingPaths) {
  const fs::path folder = FreshFolder("check");
  EXPECT_NO_THROW(CheckCanWrite(folder / "new.txt", false));
  WriteFileAtomic(folder / "old.txt", "x");
  try {
    CheckCanWrite(folder / "old.txt", false);
    FAIL() << "expected an Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("--force"), std::string::npos);
  }
  EXPECT_NO_THROW(CheckCanWrite(folder / "old.txt", true));
}

TEST(StagedDirectory, RefusesNonEmptyFolderWithoutForce) {
  const fs::path root = FreshFolder("refuse");
  WriteFileAtomic(root / "out" / "user.txt", "precious");
  EXPECT_THROW(StagedDirectory(root / "out", false), Error);
  EXPECT_EQ(ReadFile(root / "out" / "user.txt"), "precious");
  EXPECT_EQ(EntryCount(root), 1u);  // no staging folder left behind
  // An empty existing folder is fine without force.
  fs::create_directories(root / "empty");
  StagedDirectory staged(root / "empty", false);
  WriteFileAtomic(staged.path() / "a.txt", "a");
  staged.Commit();
  EXPECT_EQ(ReadFile(root / "empty" / "a.txt"), "a");
}

TEST(StagedDirectory, LeavesNothingWhenNotCommitted) {
  const fs::path root = FreshFolder("abandon");
  {
    StagedDirectory staged(root / "out", false);
    WriteFileAtomic(staged.path() / "half.txt", "half");
    EXPECT_TRUE(fs::exists(staged.path() / "half.txt"));
    EXPECT_FALSE(fs::exists(root / "out"));
  }
  EXPECT_EQ(EntryCount(root), 0u);
  // The same through an exception, as when a command fails half way.
  try {
    StagedDirectory staged(root / "out", false);
    WriteFileAtomic(staged.path() / "half.txt", "half");
    Fail("stage failed");
  } catch (const Error&) {}
  EXPECT_EQ(EntryCount(root), 0u);
}

TEST(StagedDirectory, ForceReplacesOnlyAtCommit) {
  const fs::path root = FreshFolder("replace");
  WriteFileAtomic(root / "out" / "old.txt", "old");
  StagedDirectory staged(root / "out/", true);
  WriteFileAtomic(staged.path() / "new.txt", "new");
  EXPECT_TRUE(fs::exists(root / "out" / "old.txt"));  // untouched until Commit
  staged.Commit();
  EXPECT_FALSE(fs::exists(root / "out" / "old.txt"));
  EXPECT_EQ(ReadFile(root / "out" / "new.txt"), "new");
  EXPECT_EQ(EntryCount(root), 1u);  // no ".old" or ".partial" siblings
}

TEST(StagedDirectory, RefusesAFileInTheWay) {
  const fs::path root = FreshFolder("file");
  WriteFileAtomic(root / "out", "a file");
  EXPECT_THROW(StagedDirectory(root / "out", true), Error);
}

TEST(Files, MessagesNameTheUsersPathsNotTheStagingOnes) {
  EXPECT_EQ(HideStagingNames("ws/.mattes.partial-4242/a.png: Permission denied"), "ws/mattes/a.png: Permission denied");
  EXPECT_EQ(HideStagingNames("out/.view_000.tmp-17.png: cannot write"), "out/view_000.png: cannot write");
  EXPECT_EQ(HideStagingNames("a/.b.old-9 and c/.d.partial-12"), "a/b and c/d");
  EXPECT_EQ(HideStagingNames("nothing/.hidden/here.partial"), "nothing/.hidden/here.partial");
}

TEST(Files, FilesystemErrorsNameThePathAndTheReason) {
  const fs::filesystem_error error("cannot create directories", fs::path("ws/.mattes.partial-7"),
                                   std::make_error_code(std::errc::permission_denied));
  const std::string message = DescribeFilesystemError(error);
  EXPECT_NE(message.find("ws/mattes: Permission denied"), std::string::npos) << message;
  EXPECT_EQ(message.find("partial"), std::string::npos) << message;
}

TEST(StagedDirectory, NamesTheUsersFolderWhenItCannotBeCreated) {
  const fs::path folder = FreshFolder("not_a_folder");
  WriteFileAtomic(folder / "file", "x");
  try {
    StagedDirectory stage(folder / "file" / "out", false);
    FAIL() << "a folder was made inside a file";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find((folder / "file" / "out").string()), std::string::npos) << message;
    EXPECT_EQ(message.find("partial"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace voltree
