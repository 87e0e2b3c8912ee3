// Photo studio benchmark: time to grow each preset, then time per view and in total for the
// default `voltree synth` (24 views on 2 rings + 8 held out, 4x4 supersampling) at each size,
// and the bytes written. Each run photographs into a temporary folder that is removed after.
//   voltree-bench-synth [--trees oak,pine,young-oak] [--sizes 512,1024] [--views 24] [--held-out 8]
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/progress.h"
#include "samples/studio.h"
#include "samples/tree_source.h"

namespace {
using namespace voltree;
namespace fs = std::filesystem;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

uintmax_t FolderBytes(const fs::path& folder) {
  uintmax_t bytes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) bytes += entry.file_size();
  return bytes;
}

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    if (comma > start) parts.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return parts;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Photo studio benchmark: seconds per view and in total for `voltree synth`"};
  std::string trees = "oak,pine,young-oak";
  std::vector<int> sizes = {512, 1024};
  StudioOptions studio;
  app.add_option("--trees", trees, "Comma-separated presets")->capture_default_str();
  app.add_option("--sizes", sizes, "Square image sizes")->delimiter(',')->capture_default_str();
  app.add_option("--views", studio.views, "Input views")->capture_default_str();
  app.add_option("--held-out", studio.held_out, "Held-out views")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::printf("photo studio, %u hardware threads, supersampling %dx%d (backdrop %dx%d)\n",
              std::thread::hardware_concurrency(), studio.supersample, studio.supersample, studio.backdrop_supersample,
              studio.backdrop_supersample);
  std::printf("| tree | size | views | grow s | s per view | total s | MB written |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  Progress quiet(true);
  for (const std::string& tree : SplitCommas(trees)) {
    const auto grow_start = std::chrono::steady_clock::now();
    const TreeMesh mesh = LoadTreeMesh(TreeSource{tree}, quiet, nullptr);
    const double grow_s = SecondsSince(grow_start);
    for (const int size : sizes) {
      StudioOptions options = studio;
      options.tree_name = tree;
      options.width = options.height = size;
      const fs::path folder = fs::temp_directory_path() / ("voltree_bench_synth_" + std::to_string(::getpid()));
      fs::remove_all(folder);
      const auto start = std::chrono::steady_clock::now();
      PhotographTree(mesh, options, folder, quiet);
      const double total_s = SecondsSince(start);
      const int views = options.views + options.held_out;
      std::printf("| %s | %d² | %d + %d | %.2f | %.2f | %.1f | %.1f |\n", tree.c_str(), size, options.views,
                  options.held_out, grow_s, total_s / views, total_s, FolderBytes(folder) / 1e6);
      std::fflush(stdout);
      fs::remove_all(folder);
    }
  }
  return 0;
}
