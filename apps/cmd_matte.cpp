// voltree matte DIR: alpha mattes and premultiplied foreground colours for a capture workspace.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "capture/calibrate.h"
#include "capture/matte.h"
#include "core/progress.h"

namespace voltree::app {

void AddMatteCommand(CLI::App& app) {
  auto* command =
      app.add_subcommand("matte",
                         "Cut the tree out of every photo: DIR/images/NAME -> DIR/mattes/NAME.png (8-bit alpha) and "
                         "DIR/foreground/NAME.png (RGBA, premultiplied colour)");
  struct Arguments {
    std::string dir;
    MatteWorkspaceOptions options;
    bool recheck = false;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("DIR", args->dir, "Capture workspace (with images/)")->required();
  AddMatteOptions(*command, args->options.matte);
  AddOption(*command, "--mattes", args->options.user_mattes);
  AddFlag(*command, "--recheck", args->recheck);
  AddThreadsOption(*command, args->options.threads);
  AddFlag(*command, "--force", args->options.force, "Replace existing DIR/mattes and DIR/foreground");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] {
    Progress progress(args->quiet);
    if (args->recheck) {
      HullRematteOptions rematte;
      rematte.matte = args->options.matte;
      const HullRematteResult result = RematteWorkspaceFromHull(args->dir, rematte, progress);
      for (const std::string& line : result.votes) progress.Say("matte", line);
      // The bounds found before from the first mattes (or the sparse points) may cut off what the
      // new mattes hold: the aspen's trunk at 20°, lost below 0.85 of the tree frame.
      UpdateBoundsFromMattes(args->dir, HullOptions{}, progress);
      return;
    }
    const size_t count = MatteWorkspace(args->dir, args->options, progress);
    progress.Say("matte", Str("wrote ", count, " mattes and foregrounds in ", args->dir));
  });
}

}  // namespace voltree::app
