// Safe output: files appear whole or not at all, and a user's data is never overwritten silently.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace voltree {

// Writes `bytes` to `path` via a temporary sibling and rename.
void WriteFileAtomic(const std::filesystem::path& path, std::string_view bytes);
std::string ReadFile(const std::filesystem::path& path);

// Throws Error when `path` exists and `force` is false, saying to pass --force.
void CheckCanWrite(const std::filesystem::path& path, bool force);

// Throws Error when `path` is a file, or a non-empty folder and `force` is false. Commands call it
// before slow work so that a refusal comes at once.
void CheckCanReplaceFolder(const std::filesystem::path& path, bool force);

// Messages name the user's paths, not the hidden staging siblings they are built in:
// ".NAME.partial-PID" becomes "NAME", ".NAME.tmp-PID.png" becomes "NAME.png".
std::string HideStagingNames(const std::string& message);
// A filesystem error (permission denied, disk full, ...) as a user's message naming the path.
std::string DescribeFilesystemError(const std::filesystem::filesystem_error& error);

// An output folder built in a hidden sibling ("DIR.partial-<pid>") and renamed into place by
// Commit(); destroyed without Commit() (an error, Ctrl-C through an exception) it removes the
// partial folder (on SIGINT/SIGTERM too, through core/interrupt_cleanup.h; staging folders of
// processes that died are removed when the next one starts). An existing non-empty DIR is an
// error unless `force`, then it is replaced only at Commit().
class StagedDirectory {
 public:
  StagedDirectory(std::filesystem::path final_path, bool force);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Where to write now.
  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& final_path() const { return final_; }
  void Commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace voltree
