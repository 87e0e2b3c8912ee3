// voltree calibrate DIR: cameras for a capture workspace (COLMAP, or an imported/known model),
// normalized into the tree frame: DIR/sparse/ and DIR/scene.json.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "capture/calibrate.h"
#include "core/progress.h"

namespace voltree::app {

void AddCalibrateCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "calibrate",
      "Find the cameras of DIR/images/ with COLMAP (feature_extractor, matcher, mapper), check that the photos "
      "registered, and write them in the tree frame (+Z up, origin at the trunk base) to DIR/sparse/ and "
      "DIR/scene.json; COLMAP's database, logs and raw model stay in DIR/colmap/");
  struct Arguments {
    std::string dir;
    CalibrateOptions options;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("DIR", args->dir, "Capture workspace (with images/, optionally mattes/)")->required();
  AddCalibrateOptions(*command, args->options);
  AddFlag(*command, "--force", args->options.force, "Replace DIR/sparse, DIR/scene.json and COLMAP's database");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] {
    Progress progress(args->quiet);
    const CalibrateReport report = CalibrateWorkspace(args->dir, args->options, progress);
    std::printf("registered %d/%d photos, mean reprojection error %.3f px, bounds (%s, %s) from the %s\n",
                report.registered, report.images, report.mean_reprojection_error,
                Str(report.bounds_min.transpose()).c_str(), Str(report.bounds_max.transpose()).c_str(),
                report.bounds_source.c_str());
  });
}

}  // namespace voltree::app
