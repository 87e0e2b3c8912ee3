#include "apps/voltree_app.h"

#include <cstdio>
#include <filesystem>
#include <new>

#include "apps/commands.h"
#include "apps/option_registry.h"
#include "core/check.h"
#include "core/error.h"
#include "core/files.h"
#include "core/interrupt_cleanup.h"

namespace voltree::app {

std::unique_ptr<CLI::App> MakeVoltreeApp() {
  auto app = std::make_unique<CLI::App>(
      "voltree captures real trees from photographs as compact volumetric assets and renders them.\n"
      "Pipeline: synth (photo studio) | calibrate + matte (capture) -> reconstruct -> compress -> render -> eval;\n"
      "'voltree run DIR' chains them on a workspace of photos; 'voltree batch ROOT' runs many workspaces.\n"
      "Run 'voltree COMMAND --help' for the options of a command.");
  app->require_subcommand(1);
  app->set_version_flag("--version", "voltree 0.1.0");
  AddDemoCommand(*app);
  AddSynthCommand(*app);
  AddCalibrateCommand(*app);
  AddMatteCommand(*app);
  AddReconstructCommand(*app);
  AddCompressCommand(*app);
  AddInfoCommand(*app);
  AddRenderCommand(*app);
  AddEvalCommand(*app);
  AddRunCommand(*app);
  AddBatchCommand(*app);
  AddSceneCommand(*app);
  AddLodBenchCommand(*app);
  AddWebCommand(*app);
  AddViewCommand(*app);
  return app;
}

int RunVoltree(int argc, char** argv) {
  InstallInterruptCleanup();  // Ctrl-C removes half-built output folders
  const std::unique_ptr<CLI::App> app = MakeVoltreeApp();
  const auto say = [](const char* what, const std::string& message) {
    std::fprintf(stderr, "voltree: %s: %s\n", what, message.c_str());
  };
  try {
    app->parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    for (int i = 1; i < argc; ++i)
      if (const std::string advice = RetiredFlagAdvice(argv[i]); !advice.empty()) {
        say("error", advice);
        return 1;
      }
    return app->exit(error);
  } catch (const OptionError& error) {  // a field's name is the library's; the user typed a flag
    say("error", HideStagingNames(DescribeOptionError(error)));
    return 1;
  } catch (const Error& error) {
    say("error", HideStagingNames(error.what()));
    return 1;
  } catch (const std::filesystem::filesystem_error& error) {  // permission denied, disk full: the user's to fix
    say("error", DescribeFilesystemError(error));
    return 1;
  } catch (const std::bad_alloc&) {
    say("error", "out of memory; try smaller photos, fewer octree levels or views");
    return 1;
  } catch (const std::exception& error) {  // InvariantError and anything unforeseen: a bug of ours
    say("internal error", error.what());
    return 2;
  }
  return 0;
}

}  // namespace voltree::app
