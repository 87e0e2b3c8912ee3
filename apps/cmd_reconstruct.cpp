// voltree reconstruct DIR: octree of opacities with billboard textures at every level -> DIR/volume/.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "core/error.h"
#include "core/progress.h"
#include "reconstruct/workspace.h"

namespace voltree::app {

void AddReconstructCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "reconstruct",
      "Estimate the tree's opacity on an octree by tomography from DIR/sparse (cameras), DIR/mattes and "
      "DIR/scene.json (bounds), make billboard textures from DIR/foreground for every level, cell and view, "
      "prune hidden ones, and write DIR/volume/ (volume.json + volume.bin)");
  struct Arguments {
    std::string levels = "7";
    std::string dir;
    ReconstructOptions options;
    std::string solver = "sart";
    bool no_fit = false;
    bool force = false;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  ReconstructOptions& o = args->options;
  command->add_option("DIR", args->dir, "Capture workspace (sparse/, mattes/, foreground/, scene.json)")->required();
  command->add_option("--levels", args->levels,
                      "Hierarchy levels: level 0 is the root, the finest has branching^(levels-1) cells per axis; auto: as many as the photos fill (a finest texel covers about one photo pixel)")
      ->capture_default_str();
  command->add_option("--branching", o.branching, "Cells per axis per subdivision: 2 (octree) or 3 (tri-grid, Reche 2004)")
      ->capture_default_str();
  command->add_option("--texels", o.texels, "Billboard textures are texels x texels (8 in Reche 2004)")->capture_default_str();
  command->add_option("--prune", o.prune, "Hide a texel when the alpha accumulated in front of its cell exceeds this")
      ->capture_default_str();
  command->add_option("--solver", args->solver,
                      "Opacity solver: sart (streamed SART, default) or ceres (bounded least squares, small volumes only)")
      ->capture_default_str();
  command->add_option("--iterations", o.iterations, "Solver iterations per level")->capture_default_str();
  command->add_option("--relaxation", o.relaxation, "SART relaxation lambda, in (0, 2)")->capture_default_str();
  command->add_option("--huber", o.huber, "Ceres only: Huber loss scale on the weighted ray residual (0: none)")
      ->capture_default_str();
  command->add_option("--margin", o.margin, "Root cube margin per side, as a fraction of the bounds' largest extent")
      ->capture_default_str();
  command->add_option("--carve-alpha", o.carve_alpha, "Alpha at or below which a pixel is empty for visual-hull carving")
      ->capture_default_str();
  command->add_option("--refine-depth", o.refine_min_optical_depth,
                      "Refine a cell only when sigma x cell edge (its optical depth) reaches this")
      ->capture_default_str();
  command->add_option("--billboard-scale", o.billboard_scale, "Billboard side / cell edge")->capture_default_str();
  command->add_flag("--no-fit", args->no_fit,
                    "Keep the tomography's billboards as they are: do not fit them to the photos (to compare)");
  command->add_option("--fit-iterations", o.fit.iterations, "Gauss-Newton steps of the billboard fit per level and view")
      ->capture_default_str();
  command->add_option("--fit-prior", o.fit.prior,
                      "How strongly the fit keeps the tomography's texels where the photos do not decide")
      ->capture_default_str();
  command->add_option("--fit-neighbours", o.fit.neighbours,
                      "Also fit each view's billboards to this many nearest photos, where the renderer blends them")
      ->capture_default_str();
  command->add_option("--fit-neighbour-weight", o.fit.neighbour_weight,
                      "Weight of each neighbouring photo against the view's own in the billboard fit")
      ->capture_default_str();
  command->add_option("--threads", o.threads, "Worker threads (0: all cores); the output does not depend on it")
      ->capture_default_str();
  command->add_flag("--force", args->force, "Replace an existing DIR/volume");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    if (args->solver == "sart")
      args->options.solver = SolverKind::kSart;
    else if (args->solver == "ceres")
      args->options.solver = SolverKind::kCeres;
    else
      Fail("--solver must be sart or ceres, got '", args->solver, "'");
    args->options.fit.enabled = !args->no_fit;
    args->options.levels = ParseLevels("--levels", args->levels);
    args->options.auto_levels = args->options.levels == 0;
    if (args->options.auto_levels) args->options.levels = 7;  // replaced once the photos are read
    Progress progress(args->quiet);
    ReconstructWorkspace(args->dir, args->options, args->force, &progress);
  });
}

}  // namespace voltree::app
