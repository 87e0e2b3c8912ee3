#include "lod/mesh_scene_job.h"

#include <filesystem>
#include <memory>

#include "core/error.h"
#include "lod/mesh_scene_renderer.h"
#include "render/frame_source.h"

namespace voltree {
namespace {

class MeshSceneSource : public FrameSource {
 public:
  MeshSceneSource(const Scene& scene, std::vector<TreeMesh> meshes, const MeshLodOptions& options,
                  std::vector<std::string> notes)
      : renderer_(scene, meshes, options), notes_(std::move(notes)) {
    const std::vector<std::string> more = renderer_.Notes();
    notes_.insert(notes_.end(), more.begin(), more.end());
  }
  std::vector<View> Orbit(const OrbitOptions& orbit) const override {
    return SceneOrbitCameras(renderer_.Bounds(), orbit);
  }
  Image8 Render(const View& view, const TreeRenderOptions& options, SceneFrameStats* stats) override {
    return renderer_.Render(view, options.background, options.count_fragments, stats);
  }
  GpuMemory GpuBytes() const override { return renderer_.GpuBytes(); }
  std::vector<std::string> Notes() const override { return notes_; }

 private:
  MeshSceneRenderer renderer_;
  std::vector<std::string> notes_;
};

}  // namespace

TreeSource SceneMeshSource(const SceneMeshRef& mesh) {
  TreeSource source;
  source.tree = IsTreeMeshFile(mesh.tree) ? mesh.path.string() : mesh.tree;
  source.seed = mesh.seed;
  source.up = mesh.up == "z" ? UpAxis::kZ : UpAxis::kY;
  return source;
}

std::vector<TreeMesh> LoadSceneMeshes(const Scene& scene, Progress& progress, std::vector<std::string>* notes) {
  std::vector<TreeMesh> meshes;
  for (const SceneMeshRef& ref : scene.meshes) {
    const std::string name = Str(scene.name, ": meshes.", ref.name);
    const TreeSource source = SceneMeshSource(ref);
    if (IsTreeMeshFile(ref.tree) && !std::filesystem::is_regular_file(ref.path))
      Fail(name, ": mesh file not found: ", ref.path.string());
    std::vector<std::string> warnings;
    try {
      meshes.push_back(LoadTreeMesh(source, progress, &warnings));
    } catch (const Error& error) {
      Fail(name, ": ", error.what());
    }
    for (const std::string& warning : warnings) notes->push_back(Str(name, ": ", warning));
  }
  return meshes;
}

RenderJobResult RunMeshSceneRenderJob(const RenderJobOptions& job, const MeshLodOptions& lod, Progress* progress) {
  lod.Check();
  Progress quiet(true);
  Progress& say = progress ? *progress : quiet;
  return RunRenderJob(job, progress, [&](const Scene& scene) -> std::unique_ptr<FrameSource> {
    std::vector<std::string> notes;
    std::vector<TreeMesh> meshes = LoadSceneMeshes(scene, say, &notes);
    say.Say("render", Str("preparing ", MeshLodMethodName(lod.method), " for ", meshes.size(), " meshes"));
    return std::make_unique<MeshSceneSource>(scene, std::move(meshes), lod, std::move(notes));
  });
}

}  // namespace voltree
