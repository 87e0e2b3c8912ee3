#include "pipeline/demo_folder.h"

#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

uint32_t FileCrc(const fs::path& path) {
  const std::string bytes = ReadFile(path);
  return Crc32(bytes.data(), bytes.size());
}

// A file of the previous demo that may be deleted: listed, and its bytes are still the demo's.
bool WrittenByPreviousDemo(const fs::path& output, const std::optional<DemoManifest>& previous,
                           const std::string& relative) {
  if (!previous) return false;
  const auto listed = previous->files.find(relative);
  if (listed == previous->files.end()) return false;
  const fs::path path = output / relative;
  return fs::is_regular_file(path) && FileCrc(path) == listed->second;
}

// Removes the now-empty folders above `path` up to (not including) `output`; stops at the first
// folder that still holds something (the user's files stay with their folders).
void RemoveEmptyParents(const fs::path& output, fs::path path) {
  std::error_code error;
  for (path = path.parent_path(); path != output && path.has_relative_path(); path = path.parent_path())
    if (!fs::is_empty(path, error) || error || !fs::remove(path, error)) return;
}

void MoveFile(const fs::path& from, const fs::path& to) {
  fs::create_directories(to.parent_path());
  std::error_code error;
  fs::rename(from, to, error);
  if (error) Fail(to.string(), ": cannot move the demo's file into place: ", error.message());
}

}  // namespace

DemoManifest ManifestOfFolder(const fs::path& folder) {
  DemoManifest manifest;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = entry.path().lexically_relative(folder).generic_string();
    if (relative != kDemoMarker) manifest.files[relative] = FileCrc(entry.path());
  }
  return manifest;
}

std::optional<DemoManifest> ReadDemoManifest(const fs::path& folder) {
  const fs::path marker = folder / kDemoMarker;
  if (!fs::exists(marker)) return std::nullopt;
  DemoManifest manifest;
  try {
    const nlohmann::json json = nlohmann::json::parse(ReadFile(marker));
    for (const auto& [relative, crc] : json.at("files").items()) {
      const fs::path path(relative);
      // A marker naming paths outside the folder would let the demo delete them: refuse.
      if (relative.empty() || path.is_absolute() || path.lexically_normal().string().starts_with(".."))
        Fail(marker.string(), ": files: '", relative, "' is not a path inside the folder");
      manifest.files[relative] = crc.get<uint32_t>();
    }
  } catch (const nlohmann::json::exception& error) {
    Fail(marker.string(), ": damaged demo marker (", error.what(),
         "); expected {\"files\": {PATH: CRC-32, ...}}; remove the folder yourself or choose another --output");
  }
  return manifest;
}

void WriteDemoManifest(const fs::path& folder, const DemoManifest& manifest) {
  nlohmann::json json = {{"written_by", "voltree demo"}, {"files", nlohmann::json::object()}};
  for (const auto& [relative, crc] : manifest.files) json["files"][relative] = crc;
  WriteFileAtomic(folder / kDemoMarker, json.dump(1) + "\n");
}

void CheckDemoOutput(const fs::path& output, bool force) {
  if (!fs::exists(output)) return;
  if (!fs::is_directory(output)) Fail(output.string(), " exists and is not a folder; choose another --output");
  if (force || fs::is_empty(output) || ReadDemoManifest(output)) return;
  Fail(output.string(), " is not empty and is not a previous demo's folder (it has no ", kDemoMarker,
       " marker); choose another --output, or pass --force to add the demo's files beside yours");
}

void InstallDemoFolder(const fs::path& built, const fs::path& output, bool force) {
  CheckDemoOutput(output, force);
  const DemoManifest fresh = ManifestOfFolder(built);
  if (!fs::exists(output) || fs::is_empty(output)) {
    std::error_code ignored;
    fs::remove(output, ignored);  // an empty folder: the whole build is renamed into its place
    fs::create_directories(output.parent_path().empty() ? fs::path(".") : output.parent_path());
    std::error_code error;
    fs::rename(built, output, error);
    if (error) Fail(output.string(), ": cannot move the finished demo into place: ", error.message());
    WriteDemoManifest(output, fresh);
    return;
  }
  const std::optional<DemoManifest> previous = ReadDemoManifest(output);
  // Refuse before touching anything when a new file would replace one the demo did not write.
  for (const auto& [relative, crc] : fresh.files) {
    const fs::path target = output / relative;
    if (fs::exists(target) && !WrittenByPreviousDemo(output, previous, relative))
      Fail(target.string(),
           " is not a file the demo wrote (or it was changed since); the demo never replaces "
           "your files: move it away or choose another --output");
  }
  // From here on, the marker lists everything the demo may have written, so an interrupted
  // install can be cleaned up by the next demo.
  DemoManifest both = fresh;
  std::vector<std::string> stale;
  if (previous)
    for (const auto& [relative, crc] : previous->files)
      if (WrittenByPreviousDemo(output, previous, relative)) {
        if (!fresh.files.count(relative)) stale.push_back(relative);
        if (!both.files.count(relative)) both.files[relative] = crc;
      }
  WriteDemoManifest(output, both);
  for (const std::string& relative : stale) {
    fs::remove(output / relative);
    RemoveEmptyParents(output, output / relative);
  }
  for (const auto& [relative, crc] : fresh.files) MoveFile(built / relative, output / relative);
  WriteDemoManifest(output, fresh);
}

}  // namespace voltree
