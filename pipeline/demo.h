// The one-command demo: a synthetic tree photographed in the studio, reconstructed and compressed
// into an asset, rendered on an orbit and evaluated against the studio's held-out truth, with a
// contact sheet of the photos and a summary of every stage.
#pragma once

#include <filesystem>

#include "capture/calibrate.h"
#include "compress/compress_volume.h"
#include "compress/compress_workspace.h"
#include "core/progress.h"
#include "pipeline/evaluate.h"
#include "pipeline/orbit_frames.h"
#include "reconstruct/reconstruct.h"
#include "samples/studio_options.h"
#include "samples/tree_source.h"

namespace voltree {

struct DemoOptions {
  std::filesystem::path output = "out/demo";
  TreeSource tree;                            // default: the built-in oak, seed 1
  StudioOptions studio;                       // default: 24 views on 2 rings + 8 held out, 512x512
  ReconstructOptions reconstruct;             // default: 7 octree levels, 4x4 texels
  CompressOptions compress;                   // default: up to 2048 codewords each (byte budget), CIELab, modified GLA
  OrbitFramesOptions orbit = DefaultOrbit();  // 24 frames at 512x512 into report/orbit/; frames 0: none
  bool evaluate = true;                       // report/metrics.json and report/index.html
  EvaluateOptions evaluation;                 // its workspace, report and label are set by RunDemo
  // Calibrate with COLMAP instead of using the studio's true cameras. The true input cameras are
  // kept in truth/input_sparse/, and the evaluation moves the held-out cameras into COLMAP's
  // (normalized) frame with the similarity that best maps the true input cameras onto COLMAP's.
  bool colmap = false;
  CalibrateOptions calibrate = DefaultCalibrate();
  // Write into a non-empty folder that is not a previous demo's, beside the files there (never
  // replacing one). What a previous demo wrote (listed in its .voltree-demo marker) is replaced
  // without asking, so the README's command can be run again; files added to it are kept.
  bool force = false;
  void Check() const;

  static OrbitFramesOptions DefaultOrbit();
  // COLMAP settings for the studio's 512x512 photos: 2048 features keep matching to seconds.
  static CalibrateOptions DefaultCalibrate();
};

// Writes the workspace at options.output atomically (built aside, renamed at the end):
// images/ mattes/ foreground/ sparse/ truth/ scene.json (studio; with colmap also colmap/ and
// truth/input_sparse/), volume/ (reconstruct), tree.vtree (compress), report/contact_sheet.png,
// report/orbit/ (renders), report/metrics.json + index.html + eval/ (evaluation), demo.json
// (options, timings per stage, sizes, headline metrics).
struct DemoResult {
  std::filesystem::path summary;       // demo.json
  std::filesystem::path index_html;    // empty without evaluation
  CompressWorkspaceResult compressed;  // the codebook sizes kept and made, the bytes
  LevelMetricsTable evaluation;        // empty without evaluation
  double seconds = 0;                  // all stages
};
DemoResult RunDemo(const DemoOptions& options, Progress& progress);

}  // namespace voltree
