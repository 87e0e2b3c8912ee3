#include "core/files.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {
fs::path TemporarySibling(const fs::path& path, std::string_view tag) {
  return path.parent_path() / Str(".", path.filename().string(), ".", tag, "-", ::getpid());
}
}  // namespace

void WriteFileAtomic(const fs::path& path, std::string_view bytes) {
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path());
  const fs::path temporary = TemporarySibling(path, "tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) Fail(path.string(), ": cannot open for writing");
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
  if (fs::exists(path) && !force)
    Fail(path.string(), " already exists; pass --force to overwrite it");
}

void CheckCanReplaceFolder(const fs::path& path, bool force) {
  if (fs::exists(path) && !fs::is_directory(path)) Fail(path.string(), " exists and is not a folder");
  if (fs::exists(path) && !fs::is_empty(path) && !force)
    Fail(path.string(), " exists and is not empty; pass --force to replace it");
}

StagedDirectory::StagedDirectory(fs::path final_path, bool force) : final_(std::move(final_path)) {
  if (final_.filename().empty()) final_ = final_.parent_path();  // "out/" -> "out"
  CheckCanReplaceFolder(final_, force);
  staging_ = TemporarySibling(final_, "partial");
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
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
  } else {
    fs::rename(staging_, final_, error);
    if (error) Fail(final_.string(), ": cannot move the finished folder into place: ", error.message());
  }
  committed_ = true;
}

}  // namespace voltree
