// The demo's output folder: the demo may replace what a previous demo wrote and nothing else.
// Each demo leaves a marker, `.voltree-demo`, listing every file it wrote with its CRC-32; only
// those files (unchanged since) are ever deleted. A user's files in the folder are kept, and a
// folder without the marker is refused unless --force, which then only adds the demo's files
// beside the user's and still refuses to overwrite any of them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace voltree {

inline constexpr const char* kDemoMarker = ".voltree-demo";

// What a demo wrote: paths relative to its folder ('/'-separated) -> CRC-32 of their bytes.
struct DemoManifest {
  std::map<std::string, uint32_t> files;
};

// Every regular file under `folder`, as a manifest (the marker itself excluded).
DemoManifest ManifestOfFolder(const std::filesystem::path& folder);
// The marker of `folder`, or nothing when it has none. Throws Error when the marker is damaged.
std::optional<DemoManifest> ReadDemoManifest(const std::filesystem::path& folder);
void WriteDemoManifest(const std::filesystem::path& folder, const DemoManifest& manifest);

// Refuses at once (before the slow work) what InstallDemoFolder would refuse: `output` is a file,
// or a non-empty folder without a marker and `force` is false.
void CheckDemoOutput(const std::filesystem::path& output, bool force);

// Moves the finished demo in `built` into `output`: deletes the files the previous demo wrote
// (those still as it wrote them), moves the new files in and writes the marker. Throws Error,
// before changing anything, when a new file would replace one the demo did not write.
void InstallDemoFolder(const std::filesystem::path& built, const std::filesystem::path& output, bool force);

}  // namespace voltree
