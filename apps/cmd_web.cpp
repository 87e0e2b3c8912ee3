// voltree web ASSET|SCENE -o DIR: a static page (index.html, voltree.js, data.js) that draws the
// asset or scene with WebGL2 in any browser, from disk or a static server.
#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "web/web_page.h"

namespace voltree::app {

void AddWebCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "web",
      "Write a self-contained web page that draws a .vtree asset or a scene .json with WebGL2, as `render` does "
      "(two nearest views blended, back-to-front traversal, LOD): index.html + voltree.js + data.js (the assets, "
      "base64). Opens from disk or any static server; orbit with the mouse. URL parameters: camera=W,H,FX,FY,CX,CY,"
      "QW,QX,QY,QZ,TX,TY,TZ (COLMAP PINHOLE + pose), orbit=AZIMUTH,ELEVATION,DISTANCE, background=R,G,B, tint=1, "
      "ui=0 (docs/web.md)");
  auto options = std::make_shared<WebPageOptions>();
  command->add_option("ASSET", options->input, "A .vtree asset, or a scene .json (see samples/scenes/README.md)")
      ->required();
  AddOption(*command, "--assets", options->asset_folder);
  AddOption(*command, "--output", options->output, "Output folder (built aside, renamed into place)")->required();
  AddFlag(*command, "--force", options->force, "Replace an existing output folder");
  command->callback([options] {
    const WebPageResult result = WriteWebPage(*options);
    std::printf("%s/index.html: %zu asset%s, %zu instance%s, %.1f KiB in %zu files\n", options->output.c_str(),
                result.assets, result.assets == 1 ? "" : "s", result.instances, result.instances == 1 ? "" : "s",
                result.bytes / 1024.0, result.files.size());
  });
}

}  // namespace voltree::app
