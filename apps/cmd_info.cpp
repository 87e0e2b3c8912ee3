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
      "category (uncompressed textures, VQ, GPU-resident, on disk), its chunks and the byte from which each level "
      "can be drawn; checks it fully on the way (a truncated file: its whole levels, and what is missing)");
  auto file = std::make_shared<std::string>();
  command->add_option("FILE", *file, "A .vtree asset")->required();
  command->callback([file] {
    const std::string bytes = ReadFile(*file);
    // A truncated progressive file still describes its whole levels (and says what is missing).
    VtreeLoadReport report;
    VtreeReadOptions read;
    read.allow_partial = true;
    read.report = &report;
    const VtreeAsset asset = ParseAsset(bytes, *file, read);
    std::printf("%s\n", file->c_str());
    if (report.truncated) std::printf("warning: truncated file: %s\n", report.missing.c_str());
    std::printf("%s", DescribeAsset(asset, CountAssetBytes(asset, bytes.size())).c_str());
    std::printf("chunks:\n");
    const auto chunks = ListChunks(bytes, *file, /*allow_partial=*/true);
    for (const auto& chunk : chunks) {
      if (!chunk.complete) {
        std::printf("  %s at byte %llu: cut off, the file ends at byte %zu of its %llu\n", chunk.tag.c_str(),
                    static_cast<unsigned long long>(chunk.offset), bytes.size(),
                    static_cast<unsigned long long>(chunk.offset + chunk.stored_bytes));
        continue;
      }
      std::printf(
          "  %s at byte %llu: %llu bytes%s\n", chunk.tag.c_str(), static_cast<unsigned long long>(chunk.offset),
          static_cast<unsigned long long>(chunk.stored_bytes),
          chunk.zstd ? Str(" (", chunk.raw_bytes, " raw bytes in ", chunk.payload_bytes, " of zstd)").c_str() : "");
    }
    // Progressive order: a reader holding the first N bytes draws every level whose BBRD ends by N.
    std::printf("progressive: level drawable from the first N bytes\n");
    size_t level = 0;
    for (const auto& chunk : chunks)
      if (chunk.tag == "BBRD" && chunk.complete)
        std::printf("  level %zu: %llu bytes\n", level++,
                    static_cast<unsigned long long>(chunk.offset + chunk.stored_bytes));
    if (report.truncated)
      std::printf("  the file ends at byte %llu; levels %u..%u are missing\n",
                  static_cast<unsigned long long>(report.file_bytes), report.levels_loaded, report.levels_in_file - 1);
  });
}

}  // namespace voltree::app
