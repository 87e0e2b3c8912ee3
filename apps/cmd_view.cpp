// voltree view ASSET|SCENE: the asset or scene in a desktop window, turned with the mouse.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "render/tree_renderer_job.h"
#include "view/viewer.h"

namespace voltree::app {

void AddViewCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "view",
      "Open a .vtree asset or a scene .json in a window, drawn by the same renderer as `render`, with a panel of "
      "frame time, cells, billboards, levels, views and GPU bytes. Left drag turns, right drag pans, the wheel zooms, "
      "W A S D fly, R resets; T tints levels, L switches the LOD rule, 0-9 force a level (again: automatic), V shows the nearest input view alone or the blend, P saves "
      "a screenshot (PNG + its camera as a COLMAP model, for `render --cameras`), Esc quits. Needs a display; "
      "`render` is the headless path");
  struct Arguments {
    ViewerOptions viewer;
    std::string size, background;
    bool no_panel = false;
  };
  auto args = std::make_shared<Arguments>();
  command->add_option("ASSET", args->viewer.input, "A .vtree asset, or a scene .json (see samples/scenes/README.md)")
      ->required();
  command->add_option("--assets", args->viewer.asset_folder,
                      "Scenes: folder to look their assets up in (default: the scene's folder)");
  command->add_option("--size", args->size, "Window WxH (default 1024x768)");
  command->add_option("--background", args->background, "R,G,B 0..255 (default 128,128,128, eval's grey)");
  command->add_option("--script", args->viewer.script,
                      "Scripted events, one a line: SECONDS drag|pan DX DY, scroll STEPS, key K, screenshot, quit; the "
                      "session ends after the last one");
  command->add_option("-o,--output", args->viewer.output, "Folder for screenshots (view_NNN.png, view_NNN/)")
      ->capture_default_str();
  command->add_flag("--no-panel", args->no_panel, "No statistics panel");
  command->callback([args] {
    ViewerOptions options = args->viewer;
    if (!args->size.empty()) {
      const auto size = ParseSize("--size", args->size);
      options.width = size.first, options.height = size.second;
    }
    if (!args->background.empty()) options.background = ParseBackground(args->background);
    options.panel = !args->no_panel;
    const ViewerResult result = RunViewer(options);
    std::printf("%d frames on %s, median %.2f ms per frame, %zu screenshot%s\n", result.frames, result.renderer.c_str(),
                result.median_ms, result.screenshots.size(), result.screenshots.size() == 1 ? "" : "s");
  });
}

}  // namespace voltree::app
