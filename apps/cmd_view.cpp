// voltree view ASSET|SCENE: the asset or scene in a desktop window, turned with the mouse.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "view/viewer.h"

namespace voltree::app {

void AddViewCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "view",
      "Open a .vtree asset or a scene .json in a window, drawn by the same renderer as `render`, with a panel of "
      "frame time, cells, billboards, levels, views and GPU bytes. Left drag turns, right drag pans, the wheel zooms, "
      "W A S D fly, R resets; T tints levels, L switches the LOD rule, 0-9 force a level (again: automatic), V shows "
      "the nearest input view alone or the blend, U switches pruning off and on (--unpruned), P saves a screenshot "
      "(PNG + its camera as a COLMAP model, for "
      "`render --cameras`), Esc quits. Needs a display; `render` is the headless path");
  auto viewer = std::make_shared<ViewerOptions>();
  command->add_option("ASSET", viewer->input, "A .vtree asset, or a scene .json (see samples/scenes/README.md)")
      ->required();
  AddOption(*command, "--assets", viewer->asset_folder);
  AddParsedOption<ViewerOptions>(
      *command, "--size", *viewer,
      [](const std::string& text, ViewerOptions& out) { std::tie(out.width, out.height) = ParseSize("--size", text); },
      Str(viewer->width, "x", viewer->height));
  AddBackgroundOption(*command, viewer->background);
  AddOption(*command, "--unpruned", viewer->unpruned);
  AddOption(*command, "--script", viewer->script);
  AddOption(*command, "--output", viewer->output, "Folder for screenshots (view_NNN.png, view_NNN/)")
      ->capture_default_str();
  AddFlag(*command, "--no-panel", viewer->panel);
  command->callback([viewer] {
    const ViewerResult result = RunViewer(*viewer);
    std::printf("%d frames on %s, median %.2f ms per frame, %zu screenshot%s\n", result.frames, result.renderer.c_str(),
                result.median_ms, result.screenshots.size(), result.screenshots.size() == 1 ? "" : "s");
  });
}

}  // namespace voltree::app
