#include "samples/import_gltf.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "samples/import_geometry.h"
#include "samples/import_texture.h"

// The one translation unit with tinygltf's implementation. Images are decoded by OpenImageIO
// (import_texture.h), not stb_image, so Debian's libstb-dev is not needed; external images are
// read by us too, so that a missing one becomes a warning naming it.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

namespace voltree {
namespace fs = std::filesystem;

namespace {

// Called by tinygltf for every image: keep the encoded bytes of data URIs; images in buffer
// views are read later, after their ranges are checked (tinygltf does not check them).
bool KeepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->as_is = true;
  if (image->bufferView < 0 && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// glTF factors are linear; TreeMesh materials hold sRGB-encoded colours (IEC 61966-2-1).
float SrgbFromLinear(float linear) {
  linear = std::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1 / 2.4f) - 0.055f;
}

void AppendLines(const std::string& prefix, const std::string& text, std::vector<std::string>* out) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) out->push_back(prefix + line);
}

std::string TrimmedMessage(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? std::string("unknown error") : text;
}

tinygltf::Model LoadModel(const fs::path& path, bool binary, std::vector<std::string>* warnings) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&KeepEncodedImage, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                         : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
  AppendLines(path.string() + ": ", warning, warnings);
  if (!ok) Fail(path.string(), ": cannot parse glTF: ", TrimmedMessage(error));
  for (const std::string& extension : model.extensionsRequired) {
    // Compressed geometry has accessors without buffer views; read as zeros it would silently
    // collapse the tree, so refuse it with the way out.
    if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression")
      Fail(path.string(), ": requires ", extension,
           ", which is not supported; re-export without mesh "
           "compression (e.g. gltf-transform copy, or Blender with compression off)");
    if (extension != "KHR_mesh_quantization" && extension != "KHR_texture_transform" &&
        extension.rfind("KHR_materials_", 0) != 0)
      warnings->push_back(Str(path.string(), ": requires extension ", extension, ", which is ignored"));
  }
  return model;
}

// The bytes [offset, offset + length) of buffer view `index`, after checking every range.
std::span<const uint8_t> BufferViewBytes(const tinygltf::Model& model, int index, const std::string& where) {
  if (index < 0 || size_t(index) >= model.bufferViews.size())
    Fail(where, ": buffer view ", index, " does not exist (", model.bufferViews.size(), " in the file)");
  const tinygltf::BufferView& view = model.bufferViews[index];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    Fail(where, ": buffer view ", index, " refers to buffer ", view.buffer, " of ", model.buffers.size());
  const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    Fail(where, ": buffer view ", index, " (bytes ", view.byteOffset, "+", view.byteLength,
         ") runs past the end of buffer ", view.buffer, " (", data.size(), " bytes)");
  return {data.data() + view.byteOffset, view.byteLength};
}

// Read access to one accessor's elements as floats or indices, bounds checked on construction.
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int index, const std::string& where) : where_(where) {
    if (index < 0 || size_t(index) >= model.accessors.size())
      Fail(where, ": accessor ", index, " does not exist (", model.accessors.size(), " in the file)");
    const tinygltf::Accessor& accessor = model.accessors[index];
    if (accessor.sparse.isSparse) Fail(where, ": accessor ", index, " is sparse, which is not supported");
    count_ = accessor.count;
    component_type_ = accessor.componentType;
    normalized_ = accessor.normalized;
    components_ = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    component_size_ = tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType));
    if (components_ <= 0 || component_size_ <= 0)
      Fail(where, ": accessor ", index, " has an invalid type or component type");
    if (accessor.bufferView < 0) return;  // no data: all zeros, as the spec says
    const std::span<const uint8_t> view = BufferViewBytes(model, accessor.bufferView, where);
    const int stride = accessor.ByteStride(model.bufferViews[accessor.bufferView]);
    if (stride <= 0) Fail(where, ": accessor ", index, " has an invalid byte stride");
    stride_ = size_t(stride);
    const size_t element = size_t(components_) * component_size_;
    if (count_ > 0 && (accessor.byteOffset > view.size() || count_ > view.size() ||
                       (count_ - 1) * stride_ + element > view.size() - accessor.byteOffset))
      Fail(where, ": accessor ", index, " (", count_, " elements from byte ", accessor.byteOffset, ", stride ", stride_,
           ") runs past the end of its buffer view (", view.size(), " bytes)");
    data_ = view.data() + accessor.byteOffset;
  }

  size_t count() const { return count_; }
  int components() const { return components_; }

  void ExpectComponents(int components, const char* attribute) const {
    if (components_ != components)
      Fail(where_, ": ", attribute, " has ", components_, " components per element, expected ", components);
  }

  // Component c of element i as a float; normalized integers map to [0, 1] or [-1, 1].
  float Float(size_t i, int c) const {
    if (data_ == nullptr) return 0.0f;
    const uint8_t* p = data_ + i * stride_ + size_t(c) * component_size_;
    switch (component_type_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return Load<float>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return Scaled(Load<uint8_t>(p), 255.0f);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(Scaled(Load<int8_t>(p), 127.0f), -1.0f);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return Scaled(Load<uint16_t>(p), 65535.0f);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(Scaled(Load<int16_t>(p), 32767.0f), -1.0f);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return float(Load<uint32_t>(p));
      default:
        return float(Load<double>(p));
    }
  }

  uint32_t Index(size_t i) const {
    if (data_ == nullptr) return 0;
    const uint8_t* p = data_ + i * stride_;
    switch (component_type_) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return Load<uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return Load<uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return Load<uint32_t>(p);
      default:
        Fail(where_, ": indices must be unsigned byte, short or int (component type ", component_type_, ")");
    }
  }

 private:
  template <typename T>
  static T Load(const uint8_t* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));  // glTF data need not be aligned
    return value;
  }
  float Scaled(float value, float max) const { return normalized_ ? value / max : value; }

  std::string where_;
  const uint8_t* data_ = nullptr;
  size_t count_ = 0, stride_ = 0;
  int components_ = 0, component_size_ = 0, component_type_ = 0;
  bool normalized_ = false;
};

Eigen::Matrix4d LocalTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return Eigen::Map<const Eigen::Matrix4d>(node.matrix.data());  // column-major
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  if (node.translation.size() == 3)
    transform.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)  // glTF stores x, y, z, w
    transform.rotate(
        Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]).normalized());
  if (node.scale.size() == 3) transform.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
  return transform.matrix();
}

// Triangle corners (indices into the primitive's vertices) for TRIANGLES, STRIP and FAN.
std::vector<uint32_t> TriangleCorners(int mode, const std::vector<uint32_t>& order) {
  std::vector<uint32_t> corners;
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 2; i < order.size(); ++i) {  // every other triangle flips to keep the winding
      const bool odd = i % 2 == 1;
      corners.insert(corners.end(), {order[i - 2], order[odd ? i : i - 1], order[odd ? i - 1 : i]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 2; i < order.size(); ++i) corners.insert(corners.end(), {order[0], order[i - 1], order[i]});
  } else {
    corners.assign(order.begin(), order.begin() + order.size() / 3 * 3);
  }
  return corners;
}

class GltfImporter {
 public:
  GltfImporter(fs::path path, tinygltf::Model model, std::vector<std::string>* warnings)
      : path_(std::move(path)), file_(path_.string()), model_(std::move(model)), warnings_(warnings) {}

  TreeMesh Run() {
    visited_.assign(model_.nodes.size(), false);
    for (const auto& [node, transform] : RootNodes()) VisitNode(node, transform);
    if (model_.nodes.empty())  // no hierarchy at all: the meshes as they are
      for (size_t m = 0; m < model_.meshes.size(); ++m) AppendMesh(int(m), Eigen::Matrix4d::Identity());
    return std::move(mesh_);
  }

 private:
  std::vector<std::pair<int, Eigen::Matrix4d>> RootNodes() const {
    std::vector<std::pair<int, Eigen::Matrix4d>> roots;
    if (!model_.scenes.empty()) {
      const int scene =
          model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size() ? model_.defaultScene : 0;
      for (int node : model_.scenes[scene].nodes) roots.emplace_back(node, Eigen::Matrix4d::Identity());
      return roots;
    }
    // No scene: every node that is nobody's child.
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int child : node.children)
        if (child >= 0 && size_t(child) < is_child.size()) is_child[child] = true;
    for (size_t n = 0; n < model_.nodes.size(); ++n)
      if (!is_child[n]) roots.emplace_back(int(n), Eigen::Matrix4d::Identity());
    return roots;
  }

  // Depth-first, children in file order, with an explicit stack so deep hierarchies cannot
  // overflow the call stack. glTF nodes form trees; a node reached twice (a cycle, or a child
  // of two parents) is skipped the second time with a warning.
  void VisitNode(int root, const Eigen::Matrix4d& root_parent) {
    std::vector<std::pair<int, Eigen::Matrix4d>> stack{{root, root_parent}};
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || size_t(index) >= model_.nodes.size())
        Fail(file_, ": node ", index, " does not exist (", model_.nodes.size(), " in the file)");
      if (visited_[index]) {
        warnings_->push_back(
            Str(file_, ": node ", index, " is reached twice (the node hierarchy must be a tree); skipped"));
        continue;
      }
      visited_[index] = true;
      const tinygltf::Node& node = model_.nodes[index];
      const Eigen::Matrix4d world = parent * LocalTransform(node);
      if (node.mesh >= 0) AppendMesh(node.mesh, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
        stack.emplace_back(*child, world);
    }
  }

  void AppendMesh(int index, const Eigen::Matrix4d& world) {
    if (size_t(index) >= model_.meshes.size())
      Fail(file_, ": mesh ", index, " does not exist (", model_.meshes.size(), " in the file)");
    const tinygltf::Mesh& mesh = model_.meshes[index];
    for (size_t p = 0; p < mesh.primitives.size(); ++p)
      AppendPrimitive(mesh.primitives[p], world, Str(file_, ": mesh '", mesh.name, "' (", index, ") primitive ", p));
  }

  void AppendPrimitive(const tinygltf::Primitive& primitive, const Eigen::Matrix4d& world, const std::string& where) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      warnings_->push_back(Str(where, ": mode ", mode, " (points or lines) skipped; only triangles are imported"));
      return;
    }
    const auto position_attribute = primitive.attributes.find("POSITION");
    if (position_attribute == primitive.attributes.end()) {
      warnings_->push_back(Str(where, ": no POSITION attribute; skipped"));
      return;
    }
    const AccessorReader positions(model_, position_attribute->second, where + " POSITION");
    positions.ExpectComponents(3, "POSITION");
    const size_t vertex_count = positions.count();

    std::vector<uint32_t> order;
    if (primitive.indices >= 0) {
      const AccessorReader indices(model_, primitive.indices, where + " indices");
      indices.ExpectComponents(1, "indices");
      order.resize(indices.count());
      for (size_t i = 0; i < order.size(); ++i) {
        order[i] = indices.Index(i);
        if (order[i] >= vertex_count)
          Fail(where, ": index ", order[i], " at position ", i, " is out of range (POSITION has ", vertex_count,
               " vertices)");
      }
    } else {
      order.resize(vertex_count);
      for (size_t i = 0; i < order.size(); ++i) order[i] = uint32_t(i);
    }
    std::vector<uint32_t> corners = TriangleCorners(mode, order);
    if (corners.empty()) return;

    const int material = MaterialFor(primitive.material);
    const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
    const Eigen::Matrix3d normal_matrix = linear.inverse().transpose();
    std::vector<MeshVertex> vertices(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      const Eigen::Vector4d p(positions.Float(v, 0), positions.Float(v, 1), positions.Float(v, 2), 1.0);
      vertices[v].position = (world * p).head<3>().cast<float>();
    }
    const bool has_normals =
        ReadAttribute(primitive, "NORMAL", 3, vertex_count, where, [&](size_t v, const Eigen::Vector4f& n) {
          const Eigen::Vector3d turned = normal_matrix * n.head<3>().cast<double>();
          const double length = turned.norm();
          vertices[v].normal = length > 0 ? Eigen::Vector3f((turned / length).cast<float>()) : Eigen::Vector3f::UnitZ();
        });
    ReadAttribute(primitive, Str("TEXCOORD_", uv_set_[material]), 2, vertex_count, where,
                  [&](size_t v, const Eigen::Vector4f& uv) { vertices[v].uv = uv.head<2>(); });
    ReadAttribute(primitive, "COLOR_0", 0, vertex_count, where,
                  [&](size_t v, const Eigen::Vector4f& colour) { vertices[v].tint = colour.head<3>(); });

    if (linear.determinant() < 0)  // a mirroring transform turns the winding inside out
      for (size_t t = 0; t < corners.size(); t += 3) std::swap(corners[t + 1], corners[t + 2]);
    if (!has_normals) {
      const std::vector<Eigen::Vector3f> normals = AreaWeightedNormals(vertices, corners);
      for (size_t v = 0; v < vertex_count; ++v) vertices[v].normal = normals[v];
    }

    const uint32_t base = uint32_t(mesh_.vertices.size());
    mesh_.vertices.insert(mesh_.vertices.end(), vertices.begin(), vertices.end());
    std::vector<uint32_t>& group = GroupFor(material);
    for (uint32_t corner : corners) group.push_back(base + corner);
  }

  // Calls `set(v, value)` for every vertex when the attribute exists; `components` 0 accepts
  // 3 or 4 (colours). Returns whether it existed.
  template <typename Setter>
  bool ReadAttribute(const tinygltf::Primitive& primitive, const std::string& name, int components, size_t vertex_count,
                     const std::string& where, Setter set) {
    const auto found = primitive.attributes.find(name);
    if (found == primitive.attributes.end()) return false;
    const AccessorReader reader(model_, found->second, where + " " + name);
    if (components == 0 && reader.components() != 4) reader.ExpectComponents(3, name.c_str());
    if (components != 0) reader.ExpectComponents(components, name.c_str());
    if (reader.count() != vertex_count)
      Fail(where, ": ", name, " has ", reader.count(), " elements but POSITION has ", vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      Eigen::Vector4f value = Eigen::Vector4f::Ones();
      for (int c = 0; c < reader.components(); ++c) value[c] = reader.Float(v, c);
      set(v, value);
    }
    return true;
  }

  std::vector<uint32_t>& GroupFor(int material) {
    auto [it, inserted] = group_of_material_.try_emplace(material, int(mesh_.groups.size()));
    if (inserted) mesh_.groups.push_back(MeshGroup{material, {}});
    return mesh_.groups[it->second].indices;
  }

  // Our material for glTF material `index` (-1: the default), converted on first use.
  int MaterialFor(int index) {
    if (index >= 0 && size_t(index) >= model_.materials.size())
      Fail(file_, ": material ", index, " does not exist (", model_.materials.size(), " in the file)");
    if (const auto found = material_of_gltf_.find(index); found != material_of_gltf_.end()) return found->second;
    Material material;
    int uv_set = 0;
    if (index < 0) {
      material.name = "default";
    } else {
      const tinygltf::Material& source = model_.materials[index];
      material.name = source.name.empty() ? Str("material_", index) : source.name;
      const std::vector<double>& factor = source.pbrMetallicRoughness.baseColorFactor;
      if (factor.size() == 4)
        material.base_color = {SrgbFromLinear(float(factor[0])), SrgbFromLinear(float(factor[1])),
                               SrgbFromLinear(float(factor[2])), std::clamp(float(factor[3]), 0.0f, 1.0f)};
      material.alpha_mode = source.alphaMode == "MASK"    ? AlphaMode::kMask
                            : source.alphaMode == "BLEND" ? AlphaMode::kBlend
                                                          : AlphaMode::kOpaque;
      material.alpha_cutoff = float(source.alphaCutoff);
      material.double_sided = source.doubleSided;
      const tinygltf::TextureInfo& texture = source.pbrMetallicRoughness.baseColorTexture;
      if (texture.index >= 0) {
        material.texture = TextureFor(texture.index);
        uv_set = std::max(texture.texCoord, 0);
      }
    }
    const int ours = int(mesh_.materials.size());
    mesh_.materials.push_back(material);
    uv_set_.push_back(uv_set);
    material_of_gltf_[index] = ours;
    return ours;
  }

  // Our texture for glTF texture `index`, or -1 (after a warning) when its image is unusable.
  int TextureFor(int index) {
    if (size_t(index) >= model_.textures.size())
      Fail(file_, ": texture ", index, " does not exist (", model_.textures.size(), " in the file)");
    const int image = model_.textures[index].source;
    if (image < 0 || size_t(image) >= model_.images.size()) {
      warnings_->push_back(Str(file_, ": texture ", index, " has no usable image; using a flat colour"));
      return -1;
    }
    if (const auto found = texture_of_image_.find(image); found != texture_of_image_.end()) return found->second;
    std::optional<Image8> decoded = DecodeImage(image);
    int ours = -1;
    if (decoded) {
      ours = int(mesh_.textures.size());
      mesh_.textures.push_back(std::move(*decoded));
    }
    texture_of_image_[image] = ours;
    return ours;
  }

  std::optional<Image8> DecodeImage(int index) {
    const tinygltf::Image& image = model_.images[index];
    const std::string label = image.uri.empty() || image.uri.rfind("data:", 0) == 0
                                  ? Str("image ", index, image.name.empty() ? "" : " '" + image.name + "'")
                                  : Str("texture '", image.uri, "'");
    try {
      if (image.bufferView >= 0)
        return DecodeImageRgba8(BufferViewBytes(model_, image.bufferView, Str(file_, ": ", label)), image.mimeType,
                                Str(file_, ": ", label));
      if (!image.image.empty()) return DecodeImageRgba8(image.image, image.mimeType, Str(file_, ": ", label));
      const fs::path texture_path = path_.parent_path() / PercentDecode(image.uri);
      if (image.uri.empty() || !fs::is_regular_file(texture_path)) {
        warnings_->push_back(Str(file_, ": ", label, " not found; using a flat colour"));
        return std::nullopt;
      }
      return ReadImageRgba8(texture_path);
    } catch (const Error& error) {
      warnings_->push_back(Str(file_, ": ", label, " cannot be decoded (", error.what(), "); using a flat colour"));
      return std::nullopt;
    }
  }

  fs::path path_;
  std::string file_;
  tinygltf::Model model_;
  std::vector<std::string>* warnings_;
  TreeMesh mesh_;
  std::map<int, int> material_of_gltf_, texture_of_image_, group_of_material_;
  std::vector<bool> visited_;  // per glTF node
  std::vector<int> uv_set_;    // per our material: the TEXCOORD set its texture reads
};

}  // namespace

TreeMesh ImportGltf(const fs::path& path, std::vector<std::string>* warnings) {
  // The container is told by its magic, not the extension: some tools write binary ".gltf".
  char magic[4] = {};
  std::ifstream(path, std::ios::binary).read(magic, 4);
  const bool binary = std::memcmp(magic, "glTF", 4) == 0;
  tinygltf::Model model = LoadModel(path, binary, warnings);
  return GltfImporter(path, std::move(model), warnings).Run();
}

}  // namespace voltree
