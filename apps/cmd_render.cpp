// voltree render ASSET: frames of a .vtree asset or a scene .json on an orbit or from COLMAP
// cameras, as PNGs and/or a turntable video.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "apps/option_registry.h"
#include "apps/stage_options.h"
#include "core/error.h"
#include "core/progress.h"
#include "core/vtree.h"
#include "lod/mesh_scene_job.h"
#include "render/scene.h"
#include "render/tree_renderer_job.h"

namespace voltree::app {
namespace {

// --level names an octree level of the asset; beyond its finest the renderer would clamp silently.
// A truncated file or --max-level leaves fewer levels: the check is against those the job loads.
void CheckRenderLevel(const std::filesystem::path& asset, int level, int max_level) {
  if (level < 0) Fail("--level ", level, ": expected an octree level, 0 or more");
  if (IsSceneFile(asset)) return;  // each of a scene's assets has its own levels; they clamp
  VtreeLoadReport report;
  VtreeReadOptions read;
  read.allow_partial = true;
  read.max_level = std::max(max_level, -1);  // a bad --max-level is the job's to report
  read.report = &report;
  const size_t levels = ReadAsset(asset, read).levels.size();
  const std::string why = levels < report.levels_in_file
                              ? Str(" of its 0..", report.levels_in_file - 1,
                                    report.truncated ? " (the file is truncated)" : " (--max-level)")
                              : "";
  if (size_t(level) >= levels)
    Fail("--level ", level, ": ", asset.string(), " has levels 0..", levels - 1, why, "; expected one of them");
}

struct RenderArguments {
  RenderJobOptions job;
  MeshLodOptions lod;     // with mesh_lod: the method that draws a scene's meshes
  bool mesh_lod = false;  // --lod named a mesh LOD method rather than a rule for assets
  bool quiet = false;
};

// --lod: a rule of the asset renderer (screen, planes) or a mesh LOD method (lod-bench's names).
void ParseRenderLod(const std::string& text, RenderArguments& args) {
  if (const std::optional<MeshLodMethod> method = MeshLodMethodFromName(text)) {
    args.lod.method = *method;
    args.mesh_lod = true;
    return;
  }
  if (text != "screen" && text != "planes")
    Fail("--lod '", text, "': expected a rule for .vtree assets (screen, planes) or, for a scene's meshes, a method (",
         MeshLodMethodList(), ")");
  args.job.render.lod.rule = LodRuleFromName(text);
  args.mesh_lod = false;
}

// What a frame of meshes drew, averaged over the frames.
void PrintMeshCounts(const std::vector<MeshFrameCounts>& counts) {
  double triangles = 0, points = 0, lines = 0, ellipsoids = 0, full = 0, reduced = 0;
  for (const MeshFrameCounts& c : counts) {
    triangles += double(c.triangles), points += double(c.points), lines += double(c.lines);
    ellipsoids += double(c.ellipsoids), full += double(c.full_instances), reduced += double(c.reduced_instances);
  }
  const double n = double(std::max<size_t>(counts.size(), 1));
  std::printf(
      "per frame: %.0f triangles, %.0f points, %.0f lines, %.0f ellipsoids; instances %.1f full, %.1f reduced\n",
      triangles / n, points / n, lines / n, ellipsoids / n, full / n, reduced / n);
  double occluded = 0, visible = 0, tested = 0;
  for (const MeshFrameCounts& c : counts)
    occluded += double(c.occluded_instances), visible += c.visible_sum, tested += double(c.visibility_tested);
  if (tested > 0)
    std::printf("occlusion per frame: %.1f instances lowered, mean visible fraction %.3f\n", occluded / n,
                visible / tested);
}

void PrintRenderResult(const RenderJobOptions& job, const RenderJobResult& result) {
  for (const std::string& note : result.notes) std::fprintf(stderr, "%s\n", note.c_str());
  const std::string output = job.output.string(), turntable = job.turntable.string();
  const std::string where = output.empty() ? turntable : turntable.empty() ? output : output + " and " + turntable;
  std::printf("%zu frames -> %s (%s)\n", result.frames.size(), where.c_str(), result.renderer.c_str());
  if (result.mesh_counts.empty())
    std::printf("median %.2f ms per frame, %.0f billboards per frame\n", result.median_ms, result.mean_billboards);
  else
    std::printf("median %.2f ms per frame\n", result.median_ms), PrintMeshCounts(result.mesh_counts);
  if (IsSceneFile(job.asset))
    std::printf("instances per frame: %.1f drawn, %.1f culled\n", result.mean_instances_drawn,
                result.mean_instances_culled);
  if (job.render.count_fragments) {
    if (result.mean_fragments >= 0)
      std::printf("fragments per frame: %.0f (fragment shader invocations, GL_ARB_pipeline_statistics_query)\n",
                  result.mean_fragments);
    else
      std::printf("fragments per frame: not available (%s lacks GL_ARB_pipeline_statistics_query)\n",
                  result.renderer.c_str());
  }
  std::printf("GPU memory: %.1f KiB (buffers %.1f KiB, atlases %.1f KiB)\n", result.gpu.Total() / 1024.0,
              result.gpu.buffers / 1024.0, result.gpu.atlas / 1024.0);
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "render",
      "Render a .vtree asset or a scene .json (billboards of the two input views nearest in angle, back-to-front "
      "octree "
      "traversal, LOD; scenes: ground plane, frustum culling, instances back to front) into straight-alpha RGBA PNGs "
      "and/or an .mp4 turntable; prints the median ms per frame, billboards per frame and GPU memory");
  auto args = std::make_shared<RenderArguments>();
  RenderJobOptions& o = args->job;
  command->add_option("ASSET", o.asset, "A .vtree asset, or a scene .json (see samples/scenes/README.md)")->required();
  AddOption(*command, "--assets", o.asset_folder);
  auto* orbit = AddOption(*command, "--orbit", o.orbit);
  AddOption(*command, "--cameras", o.cameras)->excludes(orbit);
  AddParsedOption<RenderJobOptions>(
      *command, "--size", o,
      [](const std::string& text, RenderJobOptions& job) {
        std::tie(job.width, job.height) = ParseSize("--size", text);
      },
      "");
  AddRenderOptions(*command, o.render);
  AddParsedOption<RenderArguments>(*command, "--lod", *args, ParseRenderLod, "screen");
  AddOption(*command, "--full-pixels", args->lod.full_pixels);
  AddOption(*command, "--min-lambda", args->lod.min_lambda);
  AddOption(*command, "--prune-seed", args->lod.seed);
  AddOption(*command, "--max-level", o.max_level);
  AddFlag(*command, "--stats", o.render.count_fragments);
  AddOption(*command, "--output", o.output, "Output folder (built aside, renamed into place)");
  AddOption(*command, "--turntable", o.turntable);
  AddFlag(*command, "--force", o.force, "Replace an existing output folder or video");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args, orbit, command] {
    RenderJobOptions job = args->job;
    // Given options are checked as given: 0 or negative frames are a mistake, not "the default".
    if (orbit->count() > 0 && job.orbit < 1)
      Fail("--orbit ", job.orbit, ": expected the number of frames, 1 or more (default 36)");
    if (command->get_option("--level")->count() > 0)
      CheckRenderLevel(job.asset, job.render.lod.forced_level, job.max_level);
    if (orbit->count() == 0 && job.cameras.empty()) job.orbit = 36;
    Progress progress(args->quiet);
    if (args->mesh_lod) {
      if (command->get_option("--level")->count() > 0)
        Fail("--level picks an octree level of .vtree assets; --lod ", MeshLodMethodName(args->lod.method),
             " draws meshes");
      PrintRenderResult(job, RunMeshSceneRenderJob(job, args->lod, &progress));
      return;
    }
    PrintRenderResult(job, RunRenderJob(job, &progress));
  });
}

}  // namespace voltree::app
