#include "samples/mesh_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.h"
#include "samples/import_frame.h"
#include "samples/import_geometry.h"
#include "samples/import_gltf.h"
#include "samples/import_obj.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

std::string Lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

void CheckFinite(const TreeMesh& mesh, const std::string& file) {
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].position.allFinite())
      Fail(file, ": vertex ", v, " has a position that is not a finite number");
}

}  // namespace

std::optional<UpAxis> UpAxisFromName(std::string_view name) {
  const std::string lower = Lowercase(std::string(name));
  if (lower == "y") return UpAxis::kY;
  if (lower == "z") return UpAxis::kZ;
  return std::nullopt;
}

void MeshImportOptions::Check() const {
  if (up != UpAxis::kY && up != UpAxis::kZ) Fail("mesh import: up axis must be Y or Z");
}

TreeMesh ImportTreeMesh(const fs::path& path, const MeshImportOptions& options, std::vector<std::string>* warnings) {
  options.Check();
  std::vector<std::string> ignored;
  if (warnings == nullptr) warnings = &ignored;
  const std::string file = path.string();
  std::error_code error;
  if (!fs::exists(path, error)) Fail(file, ": no such file");
  if (!fs::is_regular_file(path, error)) Fail(file, ": not a regular file; expected a .gltf, .glb or .obj mesh");

  const std::string extension = Lowercase(path.extension().string());
  TreeMesh mesh;
  if (extension == ".gltf" || extension == ".glb")
    mesh = ImportGltf(path, warnings);
  else if (extension == ".obj")
    mesh = ImportObj(path, warnings);
  else
    Fail(file, ": unsupported mesh format '", extension, "'; supported: .gltf, .glb, .obj");

  RemoveUnusedVertices(&mesh);
  if (mesh.TriangleCount() == 0) Fail(file, ": the mesh has no triangles");
  CheckFinite(mesh, file);
  MoveToTreeFrame(options.up, &mesh);
  try {
    mesh.Check();
  } catch (const Error& problem) {
    Fail(file, ": ", problem.what());
  }
  return mesh;
}

}  // namespace voltree
