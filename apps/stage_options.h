// The flags of each stage's options, bound to the struct a command passes: a command that runs a
// stage adds that stage's flags with one call, so `reconstruct`, `run` and `demo` accept the same
// reconstruction flags with the same meanings and defaults (help and names: option_registry.cpp).
#pragma once

#include <CLI/CLI.hpp>

#include "capture/calibrate.h"
#include "capture/matte.h"
#include "compress/compress_volume.h"
#include "compress/compress_workspace.h"
#include "pipeline/evaluate.h"
#include "pipeline/orbit_frames.h"
#include "reconstruct/reconstruct.h"
#include "render/tree_renderer.h"
#include "samples/studio_options.h"
#include "samples/tree_source.h"

namespace voltree::app {

void AddTreeSourceOptions(CLI::App& command, TreeSource& tree, StudioOptions& studio);  // --seed sets both
void AddStudioOptions(CLI::App& command, StudioOptions& studio);
void AddCalibrateOptions(CLI::App& command, CalibrateOptions& calibrate);
void AddMatteOptions(CLI::App& command, MatteOptions& matte);
void AddReconstructOptions(CLI::App& command, ReconstructOptions& reconstruct);
// For a command that reconstructs and compresses: unless --levels was given, the octree may grow
// deeper than its default where the photos fill it and `max_bytes` is predicted to hold it.
void DeepenWithinBudgetUnlessLevelsGiven(const CLI::App& command, uint64_t max_bytes, ReconstructOptions& reconstruct);
void AddCompressOptions(CLI::App& command, CompressOptions& compress);
// After a command that added AddCompressOptions compressed: warns on stderr where a codebook came out
// smaller than the user explicitly asked for (GLA cannot make more codewords than there are distinct
// billboards) and, when `quiet` silenced the progress lines that already said it, where the asset is
// over --max-bytes even at the smallest codebooks.
void WarnAboutCompression(const CLI::App& command, const CompressWorkspaceResult& compressed, uint64_t max_bytes,
                          bool quiet);
void AddOrbitOptions(CLI::App& command, OrbitFramesOptions& orbit);
void AddEvaluateOptions(CLI::App& command, EvaluateOptions& evaluate);
void AddRenderOptions(CLI::App& command, TreeRenderOptions& render);

// --background R,G,B bound to straight RGBA; the default shown is the array's ("transparent" when alpha is 0).
CLI::Option* AddBackgroundOption(CLI::App& command, std::array<float, 4>& background);

// --threads for every stage a command runs: one flag, one count.
void AddThreadsOption(CLI::App& command, int& threads);

}  // namespace voltree::app
