// Each subcommand lives in its own file and registers itself on the root app here.
// A command only parses options and calls the libraries.
#pragma once

#include <CLI/CLI.hpp>

namespace voltree::app {

void AddSynthCommand(CLI::App& app);

}  // namespace voltree::app
