// Web page benchmark: `voltree web` pages in headless Chromium (WebGL2 on SwiftShader, the CPU)
// against `voltree render` (OpenGL, llvmpipe here) on the same orbit: median ms per frame, the
// page's bytes and its time from navigation to the first frame drawn (reading the files, parsing
// and checking the assets, uploading them). One row per input (assets or scene .json).
//   voltree-bench-web INPUT... [--assets DIR] [--frames 36] [--size 512x512] [--json out.json]
// Page frames are timed as render times them: traversal, upload, draw and a wait for the GPU
// (a one-pixel read-back in the page, glFinish natively), no read-back of the image.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/option_parsing.h"
#include "core/error.h"
#include "core/files.h"
#include "render/scene.h"
#include "render/tree_renderer_job.h"
#include "web/web_page.h"

using namespace voltree;
namespace fs = std::filesystem;

namespace {

std::string Capture(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) Fail("cannot run: ", command);
  char buffer[65536];
  for (size_t n; (n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0;) output.append(buffer, n);
  ::pclose(pipe);
  return output;
}

// The page's own report (bench=N), read from the DOM Chromium prints once the page has loaded.
// No virtual time: it would stop performance.now() while the page draws.
nlohmann::json PageBench(const fs::path& page, int frames, int width, int height, bool s3tc) {
  const std::string url = "file://" + (page / "index.html").string() + "?ui=0&bench=" + std::to_string(frames) +
                          "&size=" + std::to_string(width) + "x" + std::to_string(height) + (s3tc ? "" : "&s3tc=0");
  const std::string dom = Capture(
      "timeout 600 chromium --headless=new --no-sandbox --disable-gpu --use-angle=swiftshader "
      "--enable-unsafe-swiftshader --force-device-scale-factor=1 --window-size=" +
      std::to_string(width + 100) + "," + std::to_string(height + 100) + " --dump-dom '" + url + "' 2>/dev/null");
  const size_t start = dom.find("<pre id=\"bench\" hidden=\"\">");
  const size_t end = dom.find("</pre>", start);
  if (start == std::string::npos || end == std::string::npos || end == start + 26) {
    const size_t error = dom.find("<pre id=\"error\"");
    Fail(page.string(), ": the page reported no benchmark",
         error == std::string::npos ? std::string() : ": " + dom.substr(error, 300));
  }
  return nlohmann::json::parse(dom.substr(start + 26, end - start - 26));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"voltree web pages in headless Chromium against voltree render"};
  std::vector<std::string> inputs;
  std::string assets, size = "512x512", json_path;
  int frames = 36;
  app.add_option("INPUT", inputs, "Assets (.vtree) or scenes (.json)")->required();
  app.add_option("--assets", assets, "Scenes: folder of their assets");
  app.add_option("--frames", frames, "Orbit frames")->capture_default_str();
  app.add_option("--size", size, "WxH")->capture_default_str();
  app.add_option("--json", json_path, "Also write the rows as JSON");
  CLI11_PARSE(app, argc, argv);
  try {
    if (std::system("command -v chromium > /dev/null") != 0)
      Fail("chromium is not installed (scripts/setup.sh installs it)");
    const auto [width, height] = app::ParseSize("--size", size);
    const fs::path scratch = fs::temp_directory_path() / ("voltree_bench_web_" + std::to_string(::getpid()));
    fs::remove_all(scratch);
    nlohmann::json rows = nlohmann::json::array();
    std::printf("%-18s %9s %10s %10s %10s %11s %10s %10s\n", "input", "size", "page KiB", "1st frame", "page ms",
                "page (RGBA)", "render ms", "billboards");
    for (const std::string& input : inputs) {
      const bool scene = IsSceneFile(input);
      WebPageOptions web;
      web.input = input;
      web.output = scratch / fs::path(input).stem();
      if (scene) web.asset_folder = assets;
      const WebPageResult page = WriteWebPage(web);
      const nlohmann::json s3tc = PageBench(web.output, frames, width, height, true);
      const nlohmann::json decoded = PageBench(web.output, frames, width, height, false);

      RenderJobOptions job;
      job.asset = input;
      if (scene) job.asset_folder = assets;
      job.orbit = frames;
      job.width = width, job.height = height;
      job.output = scratch / (fs::path(input).stem().string() + "_frames");
      const RenderJobResult native = RunRenderJob(job, nullptr);

      std::printf("%-18s %4dx%-4d %10.0f %8.0f ms %10.1f %11.1f %10.1f %10.0f\n", fs::path(input).filename().c_str(),
                  width, height, page.bytes / 1024.0, s3tc.at("first_frame_ms").get<double>(),
                  s3tc.at("median_ms").get<double>(), decoded.at("median_ms").get<double>(), native.median_ms,
                  native.mean_billboards);
      rows.push_back({{"input", fs::path(input).filename().string()},
                      {"width", width},
                      {"height", height},
                      {"page_bytes", page.bytes},
                      {"page", s3tc},
                      {"page_rgba8", decoded},
                      {"render_median_ms", native.median_ms},
                      {"render_billboards", native.mean_billboards},
                      {"renderer", native.renderer}});
    }
    fs::remove_all(scratch);
    if (!json_path.empty()) WriteFileAtomic(json_path, rows.dump(2) + "\n");
  } catch (const Error& error) {
    std::fprintf(stderr, "voltree-bench-web: %s\n", error.what());
    return 1;
  }
  return 0;
}
