#include "core/files.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>

#include "core/error.h"
#include "core/interrupt_cleanup.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {
fs::path TemporarySibling(const fs::path& path, std::string_view tag) {
  return path.parent_path() / Str(".", path.filename().string(), ".", tag, "-", ::getpid());
}
}  // namespace

void WriteFileAtomic(const fs::path& path, std::string_view bytes) {
  const auto writing = HoldOffInterruptCleanup();
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path());
  const fs::path temporary = TemporarySibling(path, "tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) Fail(path.string(), ": cannot open for writing (", std::strerror(errno), ")");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      Fail(path.string(), ": write failed (disk full?)");
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    Fail(path.string(), ": cannot move the finished file into place");
  }
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path.string(), ": cannot open for reading");
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

void CheckCanWrite(const fs::path& path, bool force) {
  if (fs::exists(path) && !force) Fail(path.string(), " already exists; pass --force to overwrite it");
}

void CheckCanReplaceFolder(const fs::path& path, bool force) {
  if (fs::exists(path) && !fs::is_directory(path)) Fail(path.string(), " exists and is not a folder");
  if (fs::exists(path) && !fs::is_empty(path) && !force)
    Fail(path.string(), " exists and is not empty; pass --force to replace it");
}

std::string HideStagingNames(const std::string& message) {
  // ".NAME.partial-PID" -> "NAME"; ".NAME.tmp-PID.png" -> "NAME.png"
  static const std::regex staging(R"((^|[/\s'"\[(])\.([^/\s'"\[\]]+?)\.(partial|old|tmp)-[0-9]+)");
  return std::regex_replace(message, staging, "$1$2");
}

std::string DescribeFilesystemError(const fs::filesystem_error& error) {
  std::string where = error.path1().empty() ? std::string("a file") : error.path1().string();
  if (!error.path2().empty()) where += Str(" (to ", error.path2().string(), ")");
  return HideStagingNames(Str(where, ": ", error.code().message(),
                              "; check that the folder exists and that you may "
                              "write there"));
}

StagedDirectory::StagedDirectory(fs::path final_path, bool force) : final_(std::move(final_path)) {
  if (final_.filename().empty()) final_ = final_.parent_path();  // "out/" -> "out"
  CheckCanReplaceFolder(final_, force);
  RemoveStaleStaging(final_);
  staging_ = TemporarySibling(final_, "partial");
  const auto writing = HoldOffInterruptCleanup();
  std::error_code error;
  fs::remove_all(staging_, error);
  RemoveOnInterrupt(staging_);
  fs::create_directories(staging_, error);
  if (error) {
    ForgetOnInterrupt(staging_);
    Fail(final_.string(), ": cannot create the output folder: ", error.message());
  }
}

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  ForgetOnInterrupt(staging_);
}

void StagedDirectory::Commit() {
  std::error_code error;
  if (fs::exists(final_)) {
    // Move the old folder aside first so that a failed rename can put it back.
    const fs::path old = TemporarySibling(final_, "old");
    fs::remove_all(old, error);
    fs::rename(final_, old, error);
    if (error) Fail(final_.string(), ": cannot replace the existing folder: ", error.message());
    fs::rename(staging_, final_, error);
    if (error) {
      fs::rename(old, final_, error);
      Fail(final_.string(), ": cannot move the finished folder into place");
    }
    fs::remove_all(old, error);
    ForgetOnInterrupt(staging_);
  } else {
    fs::rename(staging_, final_, error);
    if (error) Fail(final_.string(), ": cannot move the finished folder into place: ", error.message());
    ForgetOnInterrupt(staging_);
  }
  committed_ = true;
}

}  // namespace voltree
