// voltree render ASSET: frames of a .vtree asset on an orbit or from COLMAP cameras.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "core/progress.h"
#include "render/tree_renderer_job.h"

namespace voltree::app {

void AddRenderCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "render",
      "Render a .vtree asset (billboards of the two input views nearest in angle, back-to-front octree traversal, "
      "screen-space LOD) into straight-alpha RGBA PNGs; prints the median ms per frame and billboards per frame");
  struct Arguments {
    RenderJobOptions job;
    std::string asset, cameras, output, size, background;
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  RenderJobOptions& o = args->job;
  command->add_option("ASSET", args->asset, "A .vtree asset")->required();
  auto* orbit = command->add_option("--orbit", o.orbit,
                                    "N frames on a circle about the tree at the input views' mean distance and "
                                    "elevation (frame_000.png, ...)");
  command->add_option("--cameras", args->cameras,
                      "COLMAP text model folder (cameras.txt, images.txt); each frame is named after its image")
      ->excludes(orbit);
  command->add_option("--size", args->size, "WxH (default: the cameras' size; orbit 512x512)");
  command->add_option("--level", o.render.lod.forced_level, "Draw only this octree level (default: screen-space LOD)");
  command->add_option("--texel-pixels", o.render.lod.max_texel_pixels,
                      "LOD: descend while a billboard texel covers more pixels than this")
      ->capture_default_str();
  command->add_option("--background", args->background, "R,G,B 0..255, opaque (default transparent)");
  command->add_option("--billboard-scale", o.render.billboard_scale,
                      "Billboard side / cell edge, as given to reconstruct")
      ->capture_default_str();
  command->add_option("-o,--output", args->output, "Output folder (built aside, renamed into place)")->required();
  command->add_flag("--force", o.force, "Replace an existing output folder");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    RenderJobOptions job = args->job;
    job.asset = args->asset;
    job.cameras = args->cameras;
    job.output = args->output;
    if (job.orbit == 0 && job.cameras.empty()) job.orbit = 36;
    if (!args->size.empty()) {
      const auto size = ParseSize(args->size, "--size");
      job.width = size[0], job.height = size[1];
    }
    if (!args->background.empty()) job.render.background = ParseBackground(args->background);
    Progress progress(args->quiet);
    const RenderJobResult result = RunRenderJob(job, &progress);
    std::printf("%zu frames -> %s (%s)\n", result.frames.size(), args->output.c_str(), result.renderer.c_str());
    std::printf("median %.2f ms per frame, %.0f billboards per frame\n", result.median_ms, result.mean_billboards);
  });
}

}  // namespace voltree::app
