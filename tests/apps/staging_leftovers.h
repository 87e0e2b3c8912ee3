// Files a voltree command stages beside its outputs before renaming them into place
// (name.partial-*, name.tmp-*, name.old-*): after any command, finished or stopped, none may remain.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voltree::testing {

inline std::vector<std::string> StagingLeftovers(const std::filesystem::path& root) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".partial-") != std::string::npos || name.find(".tmp-") != std::string::npos ||
        name.find(".old-") != std::string::npos)
      found.push_back(entry.path().string());
  }
  return found;
}

}  // namespace voltree::testing
