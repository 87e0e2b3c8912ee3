// Placeholder until the studio lands.
#include "apps/commands.h"
namespace voltree::app {
void AddSynthCommand(CLI::App& app) { app.add_subcommand("synth", "Photograph a synthetic tree (not yet built)"); }
}  // namespace voltree::app
