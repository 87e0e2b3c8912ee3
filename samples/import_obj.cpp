#include "samples/import_obj.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "samples/import_geometry.h"
#include "samples/import_texture.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

// One OBJ corner: position, texture coordinate and normal indices (-1: absent).
struct Corner {
  int position, uv, normal;
  bool operator==(const Corner&) const = default;
};

struct CornerHash {
  size_t operator()(const Corner& c) const {
    return (size_t(uint32_t(c.position)) * 0x9E3779B97F4A7C15ull) ^ (size_t(uint32_t(c.uv)) * 0xC2B2AE3D27D4EB4Full) ^
           size_t(uint32_t(c.normal));
  }
};

// tinyobjloader reads a coordinate it cannot parse ("nan", "inf", "1,5") as 0 without a word, so
// the vertex lines are checked first: each of x, y, z must be a whole, finite number.
void CheckVertexNumbers(const fs::path& path) {
  std::ifstream in(path);
  int vertex = 0;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    ++vertex;
    std::istringstream tokens(line.substr(2));
    std::string token;
    for (int axis = 0; axis < 3 && tokens >> token; ++axis) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (*end != '\0' || !std::isfinite(value))
        Fail(path.string(), ":", number, ": vertex ", vertex, " has a coordinate '", token,
             "' that is not a finite number");
    }
  }
}

class ObjImporter {
 public:
  ObjImporter(fs::path path, std::vector<std::string>* warnings)
      : path_(std::move(path)), file_(path_.string()), warnings_(warnings) {}

  TreeMesh Run() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    const bool ok = reader.ParseFromFile(file_, config);
    std::istringstream lines(reader.Warning());
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) warnings_->push_back(Str(file_, ": ", line));
    if (!ok) Fail(file_, ": cannot parse OBJ: ", reader.Error().empty() ? "unknown error" : reader.Error());
    attrib_ = &reader.GetAttrib();
    materials_ = &reader.GetMaterials();

    std::vector<bool> needs_normal;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) AppendShape(shape, &needs_normal);
    FillMissingNormals(needs_normal);
    return std::move(mesh_);
  }

 private:
  void AppendShape(const tinyobj::shape_t& shape, std::vector<bool>* needs_normal) {
    size_t offset = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const size_t corners = shape.mesh.num_face_vertices[f];
      if (corners == 3) {
        const int material_id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
        std::vector<uint32_t>& group = GroupFor(MaterialFor(material_id));
        for (size_t k = 0; k < 3; ++k)
          group.push_back(VertexFor(shape.mesh.indices[offset + k], shape.name, needs_normal));
      }
      offset += corners;
    }
  }

  uint32_t VertexFor(const tinyobj::index_t& index, const std::string& shape, std::vector<bool>* needs_normal) {
    const Corner corner{index.vertex_index, index.texcoord_index, index.normal_index};
    if (const auto found = vertex_of_corner_.find(corner); found != vertex_of_corner_.end()) return found->second;
    CheckIndex(corner.position, attrib_->vertices.size() / 3, "vertex", shape, false);
    CheckIndex(corner.uv, attrib_->texcoords.size() / 2, "texture coordinate", shape, true);
    CheckIndex(corner.normal, attrib_->normals.size() / 3, "normal", shape, true);
    MeshVertex vertex;
    const auto& v = attrib_->vertices;
    vertex.position = {v[3 * corner.position], v[3 * corner.position + 1], v[3 * corner.position + 2]};
    if (corner.uv >= 0)  // OBJ's v runs up from the bottom row; ours from the top row
      vertex.uv = {attrib_->texcoords[2 * corner.uv], 1.0f - attrib_->texcoords[2 * corner.uv + 1]};
    if (corner.normal >= 0) {
      const auto& n = attrib_->normals;
      const Eigen::Vector3f normal(n[3 * corner.normal], n[3 * corner.normal + 1], n[3 * corner.normal + 2]);
      vertex.normal = normal.norm() > 0 ? normal.normalized() : Eigen::Vector3f::UnitZ();
    }
    const uint32_t ours = uint32_t(mesh_.vertices.size());
    mesh_.vertices.push_back(vertex);
    needs_normal->push_back(corner.normal < 0);
    vertex_of_corner_.emplace(corner, ours);
    return ours;
  }

  void CheckIndex(int index, size_t count, const char* what, const std::string& shape, bool optional) const {
    if ((optional && index == -1) || (index >= 0 && size_t(index) < count)) return;
    Fail(file_, ": a face of '", shape, "' refers to ", what, " ", index + 1, " but the file has ", count);
  }

  void FillMissingNormals(const std::vector<bool>& needs_normal) {
    if (std::find(needs_normal.begin(), needs_normal.end(), true) == needs_normal.end()) return;
    std::vector<uint32_t> triangles;
    for (const MeshGroup& group : mesh_.groups)
      triangles.insert(triangles.end(), group.indices.begin(), group.indices.end());
    const std::vector<Eigen::Vector3f> normals = AreaWeightedNormals(mesh_.vertices, triangles);
    for (size_t v = 0; v < mesh_.vertices.size(); ++v)
      if (needs_normal[v]) mesh_.vertices[v].normal = normals[v];
  }

  std::vector<uint32_t>& GroupFor(int material) {
    auto [it, inserted] = group_of_material_.try_emplace(material, int(mesh_.groups.size()));
    if (inserted) mesh_.groups.push_back(MeshGroup{material, {}});
    return mesh_.groups[it->second].indices;
  }

  int MaterialFor(int id) {
    if (id >= 0 && size_t(id) >= materials_->size()) id = -1;  // tinyobj's "unknown material"
    if (const auto found = material_of_id_.find(id); found != material_of_id_.end()) return found->second;
    const int ours = int(mesh_.materials.size());
    mesh_.materials.push_back(id < 0 ? Material{.name = "default"} : ConvertMaterial((*materials_)[id]));
    material_of_id_[id] = ours;
    return ours;
  }

  Material ConvertMaterial(const tinyobj::material_t& source) {
    Material material;
    material.name = source.name;
    const float opacity = std::clamp(float(source.dissolve), 0.0f, 1.0f);
    material.base_color = {std::clamp(float(source.diffuse[0]), 0.0f, 1.0f),
                           std::clamp(float(source.diffuse[1]), 0.0f, 1.0f),
                           std::clamp(float(source.diffuse[2]), 0.0f, 1.0f), opacity};
    const std::optional<Image8> colour = LoadTexture(source.diffuse_texname);
    const std::optional<Image8> alpha = LoadTexture(source.alpha_texname);
    if (colour) material.base_color.head<3>().setOnes();
    std::optional<Image8> texture = colour;
    if (alpha) {
      const Image8 coverage = CoverageFromAlphaMap(*alpha);
      texture = MultiplyAlpha(colour ? *colour : Image8(coverage.width, coverage.height, 4, 255), coverage);
    }
    if (texture) {
      if (HasTransparency(*texture)) {
        material.alpha_mode = AlphaMode::kMask;
        material.double_sided = true;
      }
      material.texture = int(mesh_.textures.size());
      mesh_.textures.push_back(std::move(*texture));
    }
    if (material.alpha_mode == AlphaMode::kOpaque && opacity < 1.0f) material.alpha_mode = AlphaMode::kBlend;
    return material;
  }

  // A texture named in the MTL file, relative to the OBJ's folder; each file is read once.
  std::optional<Image8> LoadTexture(std::string name) {
    if (name.empty()) return std::nullopt;
    std::replace(name.begin(), name.end(), '\\', '/');  // MTL files written on Windows
    if (const auto found = texture_cache_.find(name); found != texture_cache_.end()) return found->second;
    std::optional<Image8> image;
    const fs::path texture_path = path_.parent_path() / name;
    if (!fs::is_regular_file(texture_path)) {
      warnings_->push_back(Str(file_, ": texture '", name, "' not found; using a flat colour"));
    } else {
      try {
        image = ReadImageRgba8(texture_path);
      } catch (const Error& error) {
        warnings_->push_back(
            Str(file_, ": texture '", name, "' cannot be read (", error.what(), "); using a flat colour"));
      }
    }
    texture_cache_[name] = image;
    return image;
  }

  fs::path path_;
  std::string file_;
  std::vector<std::string>* warnings_;
  const tinyobj::attrib_t* attrib_ = nullptr;
  const std::vector<tinyobj::material_t>* materials_ = nullptr;
  TreeMesh mesh_;
  std::unordered_map<Corner, uint32_t, CornerHash> vertex_of_corner_;  // lookup only: order comes from the faces
  std::map<int, int> material_of_id_, group_of_material_;
  std::map<std::string, std::optional<Image8>> texture_cache_;
};

}  // namespace

TreeMesh ImportObj(const fs::path& path, std::vector<std::string>* warnings) {
  CheckVertexNumbers(path);
  return ObjImporter(path, warnings).Run();
}

}  // namespace voltree
