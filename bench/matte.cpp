// Matting accuracy and speed: for each workspace with true mattes (a `voltree synth` set: photos
// in images/, true mattes in mattes/, truth/meta.json naming the tree) and each refine method,
// mattes every photo and prints seconds per image, SAD (thousands) and MSE (x1e3), averaged over
// the photos (see capture/matte/metrics.h for the conventions). Without workspaces it uses the
// synthetic scene of the matting tests at a few sizes.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/matte.h"
#include "capture/photo_folder.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "samples/matte_scene.h"

namespace fs = std::filesystem;
using namespace voltree;

namespace {

struct Case {
  std::string tree;
  Image8 photo, truth;
};

std::vector<Case> LoadWorkspace(const fs::path& dir) {
  std::string tree = dir.filename().string();
  if (fs::exists(dir / "truth" / "meta.json")) {
    const auto meta = nlohmann::json::parse(ReadFile(dir / "truth" / "meta.json"));
    if (meta.contains("tree") && meta["tree"].is_string()) tree = meta["tree"].get<std::string>();
  }
  std::vector<Case> cases;
  for (const fs::path& photo : ListPhotos(dir / "images"))
    cases.push_back({tree, ReadImage8(photo, 3), ReadImage8(FindUserMatte(dir / "mattes", photo), 1)});
  return cases;
}

void Report(const std::string& tree, const std::vector<Case>& cases, RefineMethod method) {
  MatteOptions options;
  options.refine = method;
  double seconds = 0.0, sad = 0.0, mse = 0.0;
  for (const Case& c : cases) {
    const auto start = std::chrono::steady_clock::now();
    const MatteResult result = MatteImage(c.photo, options);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const MatteError error = CompareMattes(result.alpha, c.truth);
    sad += error.sad;
    mse += error.mse;
  }
  const double n = static_cast<double>(cases.size());
  std::printf("| %-12s | %5dx%-5d | %2zu | %-8s | %8.3f | %8.3f | %8.3f |\n", tree.c_str(), cases[0].photo.width,
              cases[0].photo.height, cases.size(), RefineMethodName(method).c_str(), seconds / n, sad / n, mse / n);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Matting benchmark: seconds per image, SAD and MSE against true mattes"};
  std::vector<std::string> dirs;
  std::vector<std::string> methods{"guided", "infoflow", "none"};
  std::vector<int> sizes{256, 512};
  app.add_option("DIR", dirs, "Workspaces with true mattes in mattes/ (e.g. from voltree synth)");
  app.add_option("--methods", methods, "Refine methods to compare")->capture_default_str();
  app.add_option("--sizes", sizes, "Sizes of the built-in synthetic scene when no DIR is given")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::printf("| tree         | size        |  n | refine   | s/image  | SAD (k)  | MSE e3   |\n");
    std::printf("|--------------|-------------|----|----------|----------|----------|----------|\n");
    auto run = [&](const std::vector<Case>& cases) {
      for (const std::string& method : methods) Report(cases[0].tree, cases, ParseRefineMethod(method));
    };
    if (dirs.empty())
      for (int size : sizes) {
        std::vector<Case> cases;
        for (uint32_t seed = 1; seed <= 3; ++seed) {
          const MatteScene scene = MakeMatteScene(size, size * 5 / 6, seed);
          cases.push_back({"synthetic", scene.photo, scene.alpha});
        }
        run(cases);
      }
    for (const std::string& dir : dirs) run(LoadWorkspace(dir));
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-matte: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
