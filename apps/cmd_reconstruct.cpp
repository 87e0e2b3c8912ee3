// voltree reconstruct DIR: octree of opacities with billboard textures at every level -> DIR/volume/.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "core/progress.h"
#include "reconstruct/reconstruct_workspace.h"

namespace voltree::app {

void AddReconstructCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "reconstruct",
      "Estimate the tree's opacity on an octree by tomography from DIR/sparse (cameras), DIR/mattes and "
      "DIR/scene.json (bounds), make billboard textures from DIR/foreground for every level, cell and view, "
      "fit them to the photos, prune hidden ones, and write DIR/volume/ (volume.json + volume.bin)");
  struct Arguments {
    std::string dir;
    ReconstructWorkspaceOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("DIR", args->dir, "Capture workspace (sparse/, mattes/, foreground/, scene.json)")->required();
  AddReconstructOptions(*command, args->options.reconstruct);
  AddThreadsOption(*command, args->options.reconstruct.threads);
  AddFlag(*command, "--force", args->options.force, "Replace an existing DIR/volume");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] {
    Progress progress(args->quiet);
    ReconstructWorkspace(args->dir, args->options, progress);
  });
}

}  // namespace voltree::app
