// voltree scene ASSET... -o SCENE.json: one render scene of many assets, on a grid or at surveyed
// positions (the batch workflow's last step).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "pipeline/scene_layout.h"

namespace voltree::app {

void AddSceneCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "scene",
      "Write a scene for 'voltree render' (samples/scenes/README.md) holding every ASSET once: on a square grid, "
      "or at the positions of a survey CSV (columns tree, x, y and optionally rotation in degrees about +Z and "
      "scale; tree is the asset's capture folder name, or the file's stem when it is not named tree.vtree)");
  auto options = std::make_shared<SceneLayoutOptions>();
  auto assets = std::make_shared<std::vector<std::string>>();
  command->add_option("ASSET", *assets, ".vtree assets (TREE/tree.vtree is named TREE)")->required();
  AddOption(*command, "--output", options->output, "The scene file (.json); asset paths are written relative to it")
      ->required();
  AddOption(*command, "--positions", options->positions);
  AddOption(*command, "--spacing", options->spacing);
  AddFlag(*command, "--force", options->force, "Replace an existing scene file");
  command->callback([options, assets] {
    SceneLayoutOptions o = *options;
    o.assets.assign(assets->begin(), assets->end());
    const int instances = WriteSceneLayout(o);
    std::printf("wrote %s: %d trees\n", o.output.string().c_str(), instances);
  });
}

}  // namespace voltree::app
