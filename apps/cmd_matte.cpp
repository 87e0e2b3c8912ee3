// voltree matte DIR: alpha mattes and premultiplied foreground colours for a capture workspace.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "capture/matte_hull_refine.h"
#include "capture/matte_workspace.h"
#include "core/error.h"
#include "core/progress.h"

namespace voltree::app {

void AddMatteCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "matte",
      "Cut the tree out of every photo: DIR/images/NAME -> DIR/mattes/NAME.png (8-bit alpha) and "
      "DIR/foreground/NAME.png (RGBA, premultiplied colour)");
  struct Arguments {
    std::string dir;
    std::string refine = "infoflow";
    std::string mattes;
    double horizon = -1.0;
    int band = 0;
    bool force = false;
    bool quiet = false;
    bool recheck = false;
    int threads = 0;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("DIR", args->dir, "Capture workspace (with images/)")->required();
  command->add_option("--refine", args->refine,
                      "How the unknown band is solved: infoflow (OpenCV alphamat, most accurate), guided (guided "
                      "filter, fastest), none (first estimate only)")
      ->capture_default_str();
  command->add_option("--mattes", args->mattes,
                      "Use these mattes instead (folder of PNG alpha or grey images named like the photos); "
                      "they are checked, converted and their foreground colours computed");
  command->add_option("--horizon", args->horizon,
                      "Horizon row as a fraction of the photo height from the top (0..1); default: estimated");
  command->add_option("--band", args->band, "Unknown band half-width in pixels around ground edges (0: auto)");
  command->add_flag("--force", args->force, "Replace existing DIR/mattes and DIR/foreground");
  command->add_flag("--recheck", args->recheck,
                    "Check the existing DIR/mattes against each other through the cameras in DIR/sparse/ and matte "
                    "again, inside the visual hull of the others, the photos that disagree (what 'run' does with "
                    "photos alone); their mattes and foregrounds are replaced");
  command->add_option("--threads", args->threads, "Worker threads (0: all cores)")->capture_default_str();
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    MatteWorkspaceOptions options;
    options.matte.refine = ParseRefineMethod(args->refine);
    options.matte.horizon = args->horizon;
    options.matte.band_radius = args->band;
    options.user_mattes = args->mattes;
    options.force = args->force;
    options.threads = args->threads;
    Progress progress(args->quiet);
    if (args->recheck) {
      HullRematteOptions rematte;
      rematte.matte = options.matte;
      const HullRematteResult result = RematteWorkspaceFromHull(args->dir, rematte, progress);
      for (const std::string& line : result.votes) progress.Say("matte", line);
      return;
    }
    const size_t count = MatteWorkspace(args->dir, options, progress);
    progress.Say("matte", Str("wrote ", count, " mattes and foregrounds in ", args->dir));
  });
}

}  // namespace voltree::app
