// voltree compress DIR: DIR/volume/ -> codebooks (GLA VQ), DXT5 atlas -> DIR/tree.vtree.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "compress/compress_workspace.h"
#include "core/progress.h"

namespace voltree::app {
void AddCompressCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "compress",
      "Vector-quantize the billboard textures of DIR/volume/ (CIELab GLA colour codebook, GLA alpha codebook; "
      "Linz 2006), pack the codebooks into a DXT5 atlas and write the asset DIR/tree.vtree");
  struct Arguments {
    std::string dir, output, space = "lab", gla = "modified";
    CompressOptions options;
    bool zstd = false, force = false, quiet = false;
  };
  auto args = std::make_shared<Arguments>();
  CompressOptions& o = args->options;
  command->add_option("DIR", args->dir, "Capture workspace with a reconstruction in DIR/volume/")->required();
  command->add_option("-o,--output", args->output, "Output asset (default DIR/tree.vtree)");
  command->add_option("--codebook", o.colour_codebook, "Colour codebook size (codewords of n x n texels)")
      ->capture_default_str();
  command->add_option("--alpha-codebook", o.alpha_codebook, "Alpha codebook size")->capture_default_str();
  command->add_option("--space", args->space, "Colour space of the colour codebook: lab or rgb")->capture_default_str();
  command->add_option("--gla", args->gla,
                      "modified: codeword = cluster member closest to the centroid (Linz 2006); classic: centroid")
      ->capture_default_str();
  command->add_flag("--alpha-weighted", o.alpha_weighted,
                    "Weight colour distances by texel alpha, so invisible texels do not steer the colour codebook");
  command->add_option("--tolerance", o.tolerance, "Stop GLA when the relative distortion drop is below this")
      ->capture_default_str();
  command->add_option("--iterations", o.max_iterations, "At most this many GLA iterations")->capture_default_str();
  command->add_option("--seed", o.seed, "Seed of the k-means++ initialization")->capture_default_str();
  command->add_flag("--zstd", args->zstd, "Compress the asset's chunks with zstd on disk");
  command->add_flag("--force", args->force, "Overwrite an existing output file");
  command->add_flag("--quiet", args->quiet, "No progress lines");
  command->callback([args] {
    args->options.space = ParseColourSpace(args->space);
    args->options.rule = ParseCodewordRule(args->gla);
    CompressWorkspaceOptions workspace;
    workspace.output = args->output;
    workspace.zstd = args->zstd;
    workspace.force = args->force;
    Progress progress(args->quiet);
    CompressStats stats;
    CompressWorkspace(args->dir, args->options, workspace, &progress, &stats);
    // GLA cannot make more codewords than there are distinct billboards; say so rather than
    // leave the user to find a smaller codebook in `voltree info`.
    const auto warn_if_smaller = [](const char* option, int asked, size_t made) {
      if (made < size_t(asked))
        std::fprintf(stderr,
                     "voltree: warning: %s %d: the codebook has only %zu codewords; the volume's billboards give "
                     "no more distinct ones\n",
                     option, asked, made);
    };
    warn_if_smaller("--codebook", args->options.colour_codebook, stats.colour.codebook.size());
    warn_if_smaller("--alpha-codebook", args->options.alpha_codebook, stats.alpha.codebook.size());
  });
}

}  // namespace voltree::app
