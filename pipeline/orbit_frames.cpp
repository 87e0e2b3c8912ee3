#include "pipeline/orbit_frames.h"

#include "core/error.h"

namespace voltree {

void OrbitFramesOptions::Check() const {
  if (frames < 1) FailOption("OrbitFramesOptions.frames", "must be at least 1, got ", frames);
  if (size < 16 || size > 8192) FailOption("OrbitFramesOptions.size", "must be in 16..8192 pixels, got ", size);
}

RenderJobResult RenderOrbitFrames(const std::filesystem::path& asset, const std::filesystem::path& folder,
                                  const OrbitFramesOptions& options, Progress& progress) {
  options.Check();
  RenderJobOptions job;
  job.asset = asset;
  // Relative to the frames, so the report names it the same before and after a staging rename.
  job.asset_label = asset.lexically_normal().lexically_relative(folder.lexically_normal()).string();
  job.orbit = options.frames;
  job.width = job.height = options.size;
  job.output = folder;
  job.force = options.force;
  const RenderJobResult result = RunRenderJob(job, &progress);
  progress.Say("orbit", Str(result.frames.size(), " frames at ", options.size, "x", options.size, " -> ",
                            folder.string(), ", median ", result.median_ms, " ms per frame"));
  return result;
}

}  // namespace voltree
