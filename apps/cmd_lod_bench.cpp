// voltree lod-bench: published level-of-detail methods (leaf pruning, points and lines, clustered
// ellipsoids) measured against the full mesh over a sweep of screen sizes -> table.md,
// lod_bench.json, plots/.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/option_parsing.h"
#include "apps/option_registry.h"
#include "core/error.h"
#include "core/files.h"
#include "core/progress.h"
#include "lod/lod_bench.h"
#include "lod/lod_bench_report.h"
#include "samples/tree_source.h"

namespace voltree::app {
namespace {

struct LodBenchArguments {
  TreeSource tree;
  LodBenchOptions bench;
  std::filesystem::path output;
  bool force = false;
  bool quiet = false;
};

void RunLodBenchCommand(const LodBenchArguments& args) {
  args.bench.Check();
  // Refuse an occupied output folder before the (possibly slow) tree is built.
  CheckCanReplaceFolder(args.output, args.force);
  Progress progress(args.quiet);
  std::vector<std::string> warnings;
  const TreeMesh mesh = LoadTreeMesh(args.tree, progress, &warnings);
  for (const std::string& warning : warnings) std::fprintf(stderr, "voltree: warning: %s\n", warning.c_str());
  const LodBenchResult result = RunLodBench(mesh, TreeSourceName(args.tree), args.bench, progress);
  StagedDirectory folder(args.output, args.force);
  WriteLodBench(result, folder.path(), progress);
  folder.Commit();
  if (!args.quiet) std::fputs(LodBenchTable(result).c_str(), stdout);
}

std::vector<int> ParseSizes(const std::string& text) {
  std::vector<int> sizes;
  for (double number : ParseNumbers("--sizes", text)) {
    if (number != static_cast<int>(number)) Fail("--sizes: ", number, " is not a whole number of pixels");
    sizes.push_back(static_cast<int>(number));
  }
  return sizes;
}

std::string JoinSizes(const std::vector<int>& sizes) {
  std::string text;
  for (int size : sizes) text += (text.empty() ? "" : ",") + std::to_string(size);
  return text;
}

}  // namespace

void AddLodBenchCommand(CLI::App& app) {
  auto* command = app.add_subcommand(
      "lod-bench",
      "Measure published levels of detail (stochastic pruning unscaled and with Cook et al.'s 1/lambda scaling, "
      "Neubert et al.'s PR-optimal scaling, rendering priority, quality-matched detail level and colour correction, "
      "pruning ordered by viewpoint mutual information, Deussen et al.'s "
      "points and lines, Clasen et al.'s clustered ellipsoids; with --asset, a voltree asset of the same tree) "
      "against the full mesh over a sweep of screen sizes, from the "
      "studio's held-out ring and from above. Writes table.md, lod_bench.json and plots/. "
      "Example: voltree lod-bench oak -o oak_lod");
  auto args = std::make_shared<LodBenchArguments>();
  LodBenchArguments* bound = args.get();  // what the parsers write into; `args` owns it
  command->add_option("TREE", args->tree.tree, "A preset (" + TreePresetList() + ") or a mesh file (.gltf, .glb, .obj)")
      ->required();
  AddParsedOption<uint64_t>(
      *command, "--seed", args->tree.seed,
      [bound](const std::string& text, uint64_t& seed) {
        seed = ParseCount("--seed", text);
        bound->bench.studio.seed = seed;  // one seed for the tree and the rig's rotation
      },
      std::to_string(args->tree.seed));
  AddChoice(*command, "--mesh-up", args->tree.up, {{"y", UpAxis::kY}, {"z", UpAxis::kZ}});
  AddParsedOption<std::vector<int>>(
      *command, "--sizes", args->bench.sizes,
      [](const std::string& text, std::vector<int>& out) { out = ParseSizes(text); }, JoinSizes(args->bench.sizes));
  AddOption(*command, "--min-lambda", args->bench.min_lambda);
  AddOption(*command, "--prune-seed", args->bench.seed);
  AddChoice(*command, "--priority", args->bench.priority.terms,
            {{"combined", PriorityTerms::kCombined},
             {"silhouette", PriorityTerms::kSilhouette},
             {"density", PriorityTerms::kDensity}});
  AddOption(*command, "--top-views", args->bench.top_views);
  AddOption(*command, "--asset", args->bench.asset);
  AddFlag(*command, "--save-views", args->bench.save_views);
  AddOption(*command, "--held-out", args->bench.studio.held_out);
  AddParsedOption<StudioOptions>(
      *command, "--size", args->bench.studio,
      [](const std::string& text, StudioOptions& out) { std::tie(out.width, out.height) = ParseSize("--size", text); },
      Str(args->bench.studio.width, "x", args->bench.studio.height));
  AddOption(*command, "--supersample", args->bench.studio.supersample);
  AddOption(*command, "-o,--output", args->output, "Output folder: table.md, lod_bench.json, plots/")->required();
  AddFlag(*command, "--force", args->force, "Replace the output folder if it exists and is not empty");
  AddFlag(*command, "--quiet", args->quiet);
  command->callback([args] { RunLodBenchCommand(*args); });
}

}  // namespace voltree::app
