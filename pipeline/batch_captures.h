// The captures of a batch: the folders directly under ROOT that hold images/.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree {

// The batch's own files in ROOT (the workflow's configuration, snakemake's log, the scene's log).
inline constexpr const char* kBatchFolder = ".voltree-batch";

struct BatchFolders {
  std::vector<std::string> captures;  // folder names holding images/, sorted
  std::vector<std::string> skipped;   // other folders (no images/), sorted; hidden folders are not listed
};

BatchFolders FindBatchCaptures(const std::filesystem::path& root);

}  // namespace voltree
