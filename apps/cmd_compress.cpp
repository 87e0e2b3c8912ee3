// voltree compress DIR: DIR/volume/ -> codebooks (GLA VQ), DXT5 atlas -> DIR/tree.vtree.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "compress/compress_workspace.h"
#include "core/progress.h"

namespace voltree::app {
namespace {

// GLA cannot make more codewords than there are distinct billboards; when the user asked for a
// size, say so rather than leave them to find a smaller codebook in `voltree info`. The default is
// only the largest size tried, so a small volume falling short of it is no news.
void WarnIfCodebookSmaller(const CLI::App& command, const char* option, int asked, size_t made) {
  if (command.get_option(option)->count() > 0 && made < size_t(asked))
    std::fprintf(stderr,
                 "voltree: warning: %s %d: the codebook has only %zu codewords; the volume's billboards give no "
                 "more distinct ones\n",
                 option, asked, made);
}

}  // namespace

void AddCompressCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "compress",
      "Vector-quantize the billboard textures of DIR/volume/ (CIELab GLA colour codebook, GLA alpha codebook; "
      "Linz 2006), pack the codebooks into a DXT5 atlas and write the asset DIR/tree.vtree");
  struct Arguments {
    std::string dir;
    CompressWorkspaceOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("DIR", args->dir, "Capture workspace with a reconstruction in DIR/volume/")->required();
  AddOption(*command, "--output", args->options.output, "Output asset (default DIR/tree.vtree)");
  AddCompressOptions(*command, args->options.compress);
  AddFlag(*command, "--force", args->options.force, "Overwrite an existing output file");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([command, args] {
    Progress progress(args->quiet);
    const CompressWorkspaceResult result = CompressWorkspace(args->dir, args->options, progress);
    WarnIfCodebookSmaller(*command, "--codebook", result.kept.colour_codebook, result.stats.colour.codebook.size());
    WarnIfCodebookSmaller(*command, "--alpha-codebook", result.kept.alpha_codebook, result.stats.alpha.codebook.size());
    if (!result.within_budget && args->quiet)  // else the progress lines already said it
      std::fprintf(stderr,
                   "voltree: warning: %s is %llu bytes, over --max-bytes %llu even with codebooks %d / %d; "
                   "reconstruct with fewer --levels or a lower --prune for a smaller asset\n",
                   result.asset.string().c_str(), static_cast<unsigned long long>(result.bytes),
                   static_cast<unsigned long long>(args->options.compress.max_bytes), result.kept.colour_codebook,
                   result.kept.alpha_codebook);
  });
}

}  // namespace voltree::app
