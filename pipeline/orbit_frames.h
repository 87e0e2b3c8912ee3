// Orbit renders of a workspace's asset for its report: REPORT/orbit/frame_NNN.png, through the
// same render job as `voltree render --orbit`.
#pragma once

#include <filesystem>

#include "core/progress.h"
#include "render/tree_renderer_job.h"

namespace voltree {

struct OrbitFramesOptions {
  int frames = 36;
  int size = 512;      // square frames
  bool force = false;  // replace an existing frames folder
  void Check() const;
};

// Renders `asset` on an orbit into `folder` (staged, renamed into place); transparent background.
RenderJobResult RenderOrbitFrames(const std::filesystem::path& asset, const std::filesystem::path& folder,
                                  const OrbitFramesOptions& options, Progress& progress);

}  // namespace voltree
