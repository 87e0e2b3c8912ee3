#include "compress/compress_workspace.h"

#include "core/error.h"
#include "core/files.h"
#include "core/volume_io.h"

namespace voltree {
namespace fs = std::filesystem;

CompressWorkspaceResult CompressWorkspace(const fs::path& workspace, const CompressWorkspaceOptions& options,
                                          Progress& progress) {
  options.compress.Check();
  const fs::path dir = workspace.lexically_normal();
  const fs::path output = options.output.empty() ? dir / "tree.vtree" : options.output;
  CheckCanWrite(output, options.force);  // fail before the work, not after
  progress.Say("compress", "reading " + (dir / "volume").string());
  const Volume volume = ReadVolume(dir / "volume");
  CompressResult result = CompressVolume(volume, options.compress, &progress);
  // The workspace's folder name only: an absolute path would make the bytes depend on where it lives.
  const fs::path name = dir.filename().empty() ? dir.parent_path().filename() : dir.filename();
  result.asset.provenance["source"] = options.source_name.empty() ? name.string() : options.source_name;
  VtreeWriteOptions write;
  write.zstd = options.zstd;
  write.force = options.force;
  WriteAsset(output, result.asset, write);
  progress.Say("compress", Str("wrote ", output.string(), " (", fs::file_size(output), " bytes)"));
  return {output, std::move(result.stats)};
}

}  // namespace voltree
