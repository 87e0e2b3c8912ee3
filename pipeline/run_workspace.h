// `voltree run DIR`: the whole pipeline on a user's capture workspace, each stage only as needed:
//   calibrate    when DIR/sparse/ is missing: COLMAP, then the tree frame (capture/calibrate.h);
//                first when both mattes/ and sparse/ are missing (photos alone)
//   matte        when DIR/mattes/ is missing (capture/matte/workspace.h); with photos alone the
//                mattes that disagree through the cameras are matted again (matte_hull_refine.h)
//   check        the mattes against each other and the cameras (coverage, visual hull): a guard
//   reconstruct  DIR/volume/ (reconstruct/reconstruct_workspace.h), then a guard: it reproduces the mattes
//   compress     DIR/tree.vtree (compress/compress_workspace.h)
//   orbit        DIR/report/orbit/frame_NNN.png (render job)
//   eval         DIR/report/{metrics.json,index.html,eval/}: held-out views when DIR/truth/
//                exists, always the input views (self-consistency)
// When only the cameras are missing, calibration bounds the tree with the mattes' visual hull.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "capture/calibrate.h"
#include "capture/matte.h"
#include "compress/compress_volume.h"
#include "compress/compress_workspace.h"
#include "core/progress.h"
#include "pipeline/evaluate.h"
#include "pipeline/orbit_frames.h"
#include "pipeline/reconstruction_guard.h"
#include "reconstruct/reconstruct.h"

namespace voltree {

struct RunOptions {
  std::filesystem::path workspace;
  MatteWorkspaceOptions matte;  // used when mattes/ is missing
  CalibrateOptions calibrate;   // used when sparse/ is missing
  ReconstructOptions reconstruct;
  CompressOptions compress;
  OrbitFramesOptions orbit;  // default 36 frames at 512x512
  EvaluateOptions evaluate;  // its workspace is set by RunWorkspace
  // Guards: stop, writing no asset, when the mattes cover too much or too little of a photo, when
  // they disagree with each other through the cameras, or when the reconstruction does not
  // reproduce them. Off only to inspect what garbage in gives.
  bool guards = true;
  // With photos alone (neither mattes/ nor sparse/): calibrate first, then matte, then re-matte
  // the photos whose mattes disagree with the others inside the others' visual hull. Off: the
  // mattes first and the calibration bounded by their hull (the order before).
  bool calibrate_first = true;
  HullRematteOptions rematte;
  MatteConsistencyOptions consistency;
  ReproductionOptions reproduction;
  // Replace what earlier runs left: volume/, tree.vtree, report/orbit/, and report files that
  // eval did not write. Mattes and cameras that exist are always kept (delete them to redo them).
  bool force = false;
  void Check() const;
};

struct StageTime {
  std::string stage;
  double seconds = 0;
  std::string what;  // "ran", or why it was skipped
};

struct RunResult {
  std::vector<StageTime> stages;
  std::filesystem::path asset;
  std::optional<CompressWorkspaceResult> compressed;  // when this run compressed (not resumed)
  EvaluateResult evaluation;
};

// Which stages would run and what is missing; throws Error naming the folder and what it lacks
// (no images/, no photos in it, outputs that exist without force) before any slow work.
void CheckRunWorkspace(const RunOptions& options);

RunResult RunWorkspace(const RunOptions& options, Progress& progress);

}  // namespace voltree
