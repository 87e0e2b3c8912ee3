#include "pipeline/demo.h"

#include <nlohmann/json.hpp>

#include "compress/compress_workspace.h"
#include "core/contact_sheet.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "reconstruct/workspace.h"
#include "samples/studio.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = "demo.json";

void WriteContactSheet(const fs::path& workspace) {
  std::vector<fs::path> photos;
  for (const auto& entry : fs::directory_iterator(workspace / "images")) photos.push_back(entry.path());
  std::sort(photos.begin(), photos.end());
  std::vector<Image8> images;
  for (const fs::path& photo : photos) images.push_back(ReadImage8(photo, 3));
  WriteImage(workspace / "report" / "contact_sheet.png", MakeContactSheet(images));
}

}  // namespace

void DemoOptions::Check() const {
  if (output.empty()) Fail("demo: the output folder is empty");
  studio.Check();
  reconstruct.Check();
  compress.Check();
}

fs::path RunDemo(const DemoOptions& options, Progress& progress) {
  options.Check();
  const bool previous_demo = fs::exists(options.output / kMarker);
  StagedDirectory stage(options.output, options.force || previous_demo);
  const fs::path workspace = stage.path();
  nlohmann::json summary = {{"tree", TreeSourceName(options.tree)}, {"seed", options.tree.seed}};
  auto timed = [&](const char* name, auto&& work) {
    const double start = progress.ElapsedSeconds();
    work();
    summary["seconds"][name] = progress.ElapsedSeconds() - start;
  };

  timed("synth", [&] {
    std::vector<std::string> warnings;
    const TreeMesh mesh = LoadTreeMesh(options.tree, progress, &warnings);
    for (const std::string& warning : warnings) progress.Say("tree", "warning: " + warning);
    StudioOptions studio = options.studio;
    studio.tree_name = TreeSourceName(options.tree);
    PhotographTree(mesh, studio, workspace, progress, /*force=*/true);  // into the empty staging folder
    WriteContactSheet(workspace);
  });
  timed("reconstruct", [&] { ReconstructWorkspace(workspace, options.reconstruct, false, &progress); });
  CompressStats compress_stats;
  timed("compress", [&] {
    CompressWorkspace(workspace, options.compress, {}, &progress, &compress_stats);
  });
  summary["texture_psnr_db"] = {{"vq", compress_stats.psnr_vq}, {"dxt5", compress_stats.psnr_dxt5}};
  summary["asset_bytes"] = fs::file_size(workspace / "tree.vtree");
  summary["options"] = {{"reconstruct", options.reconstruct.ToJson()}, {"compress", options.compress.ToJson()}};
  WriteFileAtomic(workspace / kMarker, summary.dump(2) + "\n");
  stage.Commit();
  progress.Say("demo", Str("done: ", options.output.string(), " (contact sheet: ",
                           (options.output / "report" / "contact_sheet.png").string(), ", asset: ",
                           (options.output / "tree.vtree").string(), ")"));
  return options.output / kMarker;
}

}  // namespace voltree
