#include "compress/compress_workspace.h"

#include "core/error.h"
#include "core/files.h"
#include "reconstruct/volume_io.h"

namespace voltree {
namespace fs = std::filesystem;

fs::path CompressWorkspace(const fs::path& workspace, const CompressOptions& options,
                           const CompressWorkspaceOptions& workspace_options, Progress* progress,
                           CompressStats* stats) {
  options.Check();
  const fs::path dir = workspace.lexically_normal();
  const fs::path output = workspace_options.output.empty() ? dir / "tree.vtree" : workspace_options.output;
  CheckCanWrite(output, workspace_options.force);  // fail before the work, not after
  if (progress) progress->Say("compress", "reading " + (dir / "volume").string());
  const Volume volume = ReadVolume(dir / "volume");
  CompressResult result = CompressVolume(volume, options, progress);
  // The workspace's folder name only: an absolute path would make the bytes depend on where it lives.
  const fs::path name = dir.filename().empty() ? dir.parent_path().filename() : dir.filename();
  result.asset.provenance["source"] =
      workspace_options.source_name.empty() ? name.string() : workspace_options.source_name;
  VtreeWriteOptions write;
  write.zstd = workspace_options.zstd;
  write.force = workspace_options.force;
  WriteAsset(output, result.asset, write);
  if (progress) progress->Say("compress", Str("wrote ", output.string(), " (", fs::file_size(output), " bytes)"));
  if (stats) *stats = std::move(result.stats);
  return output;
}

}  // namespace voltree
