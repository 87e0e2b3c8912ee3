#include "pipeline/batch_captures.h"

#include <algorithm>

namespace voltree {
namespace fs = std::filesystem;

BatchFolders FindBatchCaptures(const fs::path& root) {
  BatchFolders folders;
  for (const fs::directory_entry& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || !entry.is_directory()) continue;  // .snakemake/, the batch's own files
    (fs::is_directory(entry.path() / "images") ? folders.captures : folders.skipped).push_back(name);
  }
  std::sort(folders.captures.begin(), folders.captures.end());
  std::sort(folders.skipped.begin(), folders.skipped.end());
  return folders;
}

}  // namespace voltree
