// The voltree command line: the root app with every subcommand, and running it the way main()
// does (errors printed as the user should read them, exit codes).
#pragma once

#include <CLI/CLI.hpp>

#include <memory>

namespace voltree::app {

std::unique_ptr<CLI::App> MakeVoltreeApp();

// Parses and runs; returns the exit code: 0, 1 for the user's errors, 2 for internal ones.
int RunVoltree(int argc, char** argv);

}  // namespace voltree::app
