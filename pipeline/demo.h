// The one-command demo: a synthetic tree photographed in the studio, reconstructed and compressed
// into an asset, with a contact sheet of the photos and a summary of every stage.
#pragma once

#include <filesystem>

#include "compress/compress_volume.h"
#include "core/progress.h"
#include "reconstruct/reconstruct.h"
#include "samples/studio_options.h"
#include "samples/tree_source.h"

namespace voltree {

struct DemoOptions {
  std::filesystem::path output = "out/demo";
  TreeSource tree;                 // default: the built-in oak, seed 1
  StudioOptions studio;            // default: 24 views on 2 rings + 8 held out, 512x512
  ReconstructOptions reconstruct;  // default: 7 octree levels, 4x4 texels
  CompressOptions compress;        // default: 512 colour and 512 alpha codewords, CIELab, modified GLA
  // Replace an output folder that is not a previous demo's. A previous demo's folder (it holds
  // demo.json) is replaced without asking, so the README's command can be run again.
  bool force = false;
  void Check() const;
};

// Writes the workspace at options.output atomically (built aside, renamed at the end):
// images/ mattes/ foreground/ sparse/ truth/ scene.json (studio), volume/ (reconstruct),
// tree.vtree (compress), report/contact_sheet.png, demo.json (options, timings, sizes).
// Returns the path of demo.json.
std::filesystem::path RunDemo(const DemoOptions& options, Progress& progress);

}  // namespace voltree
