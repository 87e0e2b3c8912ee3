// Each subcommand lives in its own file and registers itself on the root app here.
// A command only parses options and calls the libraries.
#pragma once

#include <CLI/CLI.hpp>

namespace voltree::app {

void AddDemoCommand(CLI::App& app);
void AddSynthCommand(CLI::App& app);
void AddCalibrateCommand(CLI::App& app);
void AddMatteCommand(CLI::App& app);
void AddReconstructCommand(CLI::App& app);
void AddCompressCommand(CLI::App& app);
void AddInfoCommand(CLI::App& app);
void AddRenderCommand(CLI::App& app);
void AddEvalCommand(CLI::App& app);
void AddRunCommand(CLI::App& app);
void AddWebCommand(CLI::App& app);
void AddViewCommand(CLI::App& app);
void AddBatchCommand(CLI::App& app);
void AddSceneCommand(CLI::App& app);
void AddLodBenchCommand(CLI::App& app);

}  // namespace voltree::app
