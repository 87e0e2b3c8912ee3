// voltree render ASSET: frames of a .vtree asset or a scene .json on an orbit or from COLMAP
// cameras, as PNGs and/or a turntable video.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/vtree.h"
#include "render/scene.h"
#include "render/tree_renderer_job.h"

namespace voltree::app {
namespace {

// --level names an octree level of the asset; beyond its finest the renderer would clamp silently.
void CheckRenderLevel(const std::string& asset, int level) {
  if (level < 0) Fail("--level ", level, ": expected an octree level, 0 or more");
  if (IsSceneFile(asset)) return;  // each of a scene's assets has its own levels; they clamp
  const size_t levels = ReadAsset(asset).levels.size();
  if (size_t(level) >= levels)
    Fail("--level ", level, ": ", asset, " has levels 0..", levels - 1, "; expected one of them");
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "render",
      "Render a .vtree asset or a scene .json (billboards of the two input views nearest in angle, back-to-front octree "
      "traversal, LOD; scenes: ground plane, frustum culling, instances back to front) into straight-alpha RGBA PNGs "
      "and/or an .mp4 turntable; prints the median ms per frame, billboards per frame and GPU memory");
  struct Arguments {
    RenderJobOptions job;
    std::string asset, cameras, output, size, background, assets, turntable, lod = "screen";
    bool quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  RenderJobOptions& o = args->job;
  command->add_option("ASSET", args->asset, "A .vtree asset, or a scene .json (see samples/scenes/README.md)")->required();
  command->add_option("--assets", args->assets, "Scenes: folder to look their assets up in (default: the scene's folder)");
  auto* orbit = command->add_option("--orbit", o.orbit,
                                    "N frames on a circle about the tree at the input views' mean distance and "
                                    "elevation (frame_000.png, ...)");
  command->add_option("--cameras", args->cameras,
                      "COLMAP text model folder (cameras.txt, images.txt); each frame is named after its image")
      ->excludes(orbit);
  command->add_option("--size", args->size, "WxH (default: the cameras' size; orbit 512x512)");
  auto* level = command->add_option("--level", o.render.lod.forced_level, "Draw only this octree level (default: LOD)");
  command->add_option("--lod", args->lod,
                      "LOD rule: screen (Euclidean distance to each cell) or planes (Linz 2006: depth along the view "
                      "direction)")
      ->capture_default_str();
  command->add_flag("--tint-levels", o.render.tint_levels, "Colour billboards by octree level (to see the LOD)");
  command->add_option("--texel-pixels", o.render.lod.max_texel_pixels,
                      "LOD: descend while a billboard texel covers more pixels than this")
      ->capture_default_str();
  command->add_option("--background", args->background, "R,G,B 0..255, opaque (default transparent)");
  command->add_option("--billboard-scale", o.render.billboard_scale,
                      "Billboard side / cell edge, as given to reconstruct")
      ->capture_default_str();
  command->add_option("-o,--output", args->output, "Output folder (built aside, renamed into place)");
  command->add_option("--turntable", args->turntable,
                      "Also (or only) encode the orbit frames as an H.264 .mp4 at 30 fps over the background (grey "
                      "when transparent); needs ffmpeg");
  command->add_flag("--force", o.force, "Replace an existing output folder or video");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args, orbit, level] {
    RenderJobOptions job = args->job;
    // Given options are checked as given: 0 or negative frames are a mistake, not "the default".
    if (orbit->count() > 0 && job.orbit < 1)
      Fail("--orbit ", job.orbit, ": expected the number of frames, 1 or more (default 36)");
    if (level->count() > 0) CheckRenderLevel(args->asset, job.render.lod.forced_level);
    job.asset = args->asset;
    job.cameras = args->cameras;
    job.output = args->output;
    job.asset_folder = args->assets;
    job.turntable = args->turntable;
    job.render.lod.rule = LodRuleFromName(args->lod);
    if (job.orbit == 0 && job.cameras.empty()) job.orbit = 36;
    if (!args->size.empty()) {
      const auto size = ParseSize(args->size, "--size");
      job.width = size[0], job.height = size[1];
    }
    if (!args->background.empty()) job.render.background = ParseBackground(args->background);
    Progress progress(args->quiet);
    const RenderJobResult result = RunRenderJob(job, &progress);
    const std::string where = args->output.empty() ? args->turntable
                              : args->turntable.empty() ? args->output
                                                        : args->output + " and " + args->turntable;
    std::printf("%zu frames -> %s (%s)\n", result.frames.size(), where.c_str(), result.renderer.c_str());
    std::printf("median %.2f ms per frame, %.0f billboards per frame\n", result.median_ms, result.mean_billboards);
    if (IsSceneFile(job.asset))
      std::printf("instances per frame: %.1f drawn, %.1f culled\n", result.mean_instances_drawn,
                  result.mean_instances_culled);
    std::printf("GPU memory: %.1f KiB (buffers %.1f KiB, atlases %.1f KiB)\n", result.gpu.Total() / 1024.0,
                result.gpu.buffers / 1024.0, result.gpu.atlas / 1024.0);
  });
}

}  // namespace voltree::app
