#include "compress/compress_workspace.h"

#include "compress/byte_budget.h"
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
  // The workspace's folder name only: an absolute path would make the bytes depend on where it lives.
  const fs::path name = dir.filename().empty() ? dir.parent_path().filename() : dir.filename();
  VtreeWriteOptions write;
  write.zstd = options.compress.zstd;
  const auto serialize = [&](VtreeAsset& asset) {
    asset.provenance["source"] = options.source_name.empty() ? name.string() : options.source_name;
    return SerializeAsset(asset, write);
  };
  BudgetedCompression budgeted = CompressWithinBudget(volume, options.compress, serialize, &progress);
  CheckCanWrite(output, options.force);
  WriteFileAtomic(output, budgeted.bytes);
  progress.Say("compress", Str("wrote ", output.string(), " (", budgeted.bytes.size(), " bytes)"));
  if (!budgeted.fits)
    progress.Say("compress",
                 Str("warning: ", budgeted.bytes.size(), " bytes, over the budget of ", options.compress.max_bytes,
                     " bytes even with codebooks ", budgeted.result.stats.colour.codebook.size(), " / ",
                     budgeted.result.stats.alpha.codebook.size(),
                     "; reconstruct with fewer --levels or a lower --prune for a smaller asset"));
  return {output, budgeted.bytes.size(), budgeted.fits, budgeted.kept, std::move(budgeted.result.stats)};
}

}  // namespace voltree
