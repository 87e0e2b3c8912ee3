// voltree: capture trees from photographs as compact volumetric assets and render them.
#include <cstdio>
#include <filesystem>
#include <new>

#include "apps/commands.h"
#include "core/error.h"
#include "core/files.h"
#include "core/interrupt_cleanup.h"

int main(int argc, char** argv) {
  CLI::App app{
      "voltree captures real trees from photographs as compact volumetric assets and renders them.\n"
      "Pipeline: synth (photo studio) | calibrate + matte (capture) -> reconstruct -> compress -> render -> eval;\n"
      "'voltree run DIR' chains them on a workspace of photos; 'voltree batch ROOT' runs many workspaces.\n"
      "Run 'voltree COMMAND --help' for the options of a command."};
  voltree::InstallInterruptCleanup();  // Ctrl-C removes half-built output folders
  app.require_subcommand(1);
  app.set_version_flag("--version", "voltree 0.1.0");
  voltree::app::AddDemoCommand(app);
  voltree::app::AddSynthCommand(app);
  voltree::app::AddCalibrateCommand(app);
  voltree::app::AddMatteCommand(app);
  voltree::app::AddReconstructCommand(app);
  voltree::app::AddCompressCommand(app);
  voltree::app::AddInfoCommand(app);
  voltree::app::AddRenderCommand(app);
  voltree::app::AddEvalCommand(app);
  voltree::app::AddRunCommand(app);
  voltree::app::AddBatchCommand(app);
  voltree::app::AddSceneCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const voltree::Error& error) {
    std::fprintf(stderr, "voltree: error: %s\n", voltree::HideStagingNames(error.what()).c_str());
    return 1;
  } catch (const std::filesystem::filesystem_error& error) {  // permission denied, disk full: the user's to fix
    std::fprintf(stderr, "voltree: error: %s\n", voltree::DescribeFilesystemError(error).c_str());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "voltree: error: out of memory; try smaller photos, fewer octree levels or views\n");
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "voltree: internal error: %s\n", error.what());
    return 2;
  }
  return 0;
}
