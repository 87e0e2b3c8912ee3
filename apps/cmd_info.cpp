// voltree info FILE: what a .vtree asset holds and where its bytes go.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "compress/asset_accounting.h"
#include "core/error.h"
#include "core/files.h"
#include "core/vtree.h"

namespace voltree::app {

void AddInfoCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "info",
      "Print a .vtree asset's levels, cells and billboards per level, views, codebook sizes and bytes by "
      "category (uncompressed textures, VQ, GPU-resident, on disk); checks it fully on the way");
  auto file = std::make_shared<std::string>();
  command->add_option("FILE", *file, "A .vtree asset")->required();
  command->callback([file] {
    const std::string bytes = ReadFile(*file);
    const VtreeAsset asset = ParseAsset(bytes, *file);
    std::printf("%s\n", file->c_str());
    std::printf("%s", DescribeAsset(asset, CountAssetBytes(asset, bytes.size())).c_str());
    std::printf("chunks:\n");
    for (const auto& chunk : ListChunks(bytes, *file))
      std::printf("  %s at byte %llu: %llu bytes%s\n", chunk.tag.c_str(), static_cast<unsigned long long>(chunk.offset),
                  static_cast<unsigned long long>(chunk.stored_bytes),
                  chunk.zstd ? Str(" (zstd, ", chunk.raw_bytes, " raw)").c_str() : "");
  });
}

}  // namespace voltree::app
