// voltree compress DIR: DIR/volume/ -> codebooks (GLA VQ), DXT5 atlas -> DIR/tree.vtree.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "compress/compress_workspace.h"
#include "core/progress.h"

namespace voltree::app {

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
    WarnAboutCompression(*command, result, args->options.compress.max_bytes, args->quiet);
  });
}

}  // namespace voltree::app
