// Mesh import: glTF (.gltf with an embedded buffer, .glb) and OBJ/MTL files written by the test
// into a temporary folder, imported, and checked against hand-computed positions and pixels.
#include "samples/mesh_import.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"
#include "core/image.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// Positions are small integers scaled and rotated in float: 1e-5 is far above float rounding
// of these values (~1e-6) and far below any wrong transform (>= 1).
constexpr float kTolerance = 1e-5f;

std::string Base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t chunk = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) chunk |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) chunk |= uint32_t(uint8_t(bytes[i + 2]));
    const size_t present = std::min<size_t>(3, bytes.size() - i);  // n bytes -> n + 1 digits
    for (size_t k = 0; k < 4; ++k) out += k <= present ? kAlphabet[(chunk >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// Accumulates one binary buffer with its views and accessors, then writes .gltf or .glb.
class GltfBuilder {
 public:
  GltfBuilder() { doc_ = {{"asset", {{"version", "2.0"}}}}; }
  json& doc() { return doc_; }

  int AddView(const std::string& bytes) {
    while (bin_.size() % 4 != 0) bin_ += '\0';
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}});
    bin_ += bytes;
    return int(doc_["bufferViews"].size()) - 1;
  }
  int AddFloats(const std::vector<float>& values, int components) {
    const int view = AddView(std::string(reinterpret_cast<const char*>(values.data()), values.size() * 4));
    const char* type = components == 2 ? "VEC2" : components == 3 ? "VEC3" : "VEC4";
    doc_["accessors"].push_back(
        {{"bufferView", view}, {"componentType", 5126}, {"count", values.size() / components}, {"type", type}});
    return int(doc_["accessors"].size()) - 1;
  }
  int AddIndices(const std::vector<uint16_t>& values) {
    const int view = AddView(std::string(reinterpret_cast<const char*>(values.data()), values.size() * 2));
    doc_["accessors"].push_back(
        {{"bufferView", view}, {"componentType", 5123}, {"count", values.size()}, {"type", "SCALAR"}});
    return int(doc_["accessors"].size()) - 1;
  }
  int AddMesh(json primitive) {
    doc_["meshes"].push_back({{"primitives", json::array({primitive})}});
    return int(doc_["meshes"].size()) - 1;
  }
  int AddNode(json node) {
    doc_["nodes"].push_back(node);
    return int(doc_["nodes"].size()) - 1;
  }

  std::string Gltf() const {
    json doc = doc_;
    doc["buffers"] =
        json::array({{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + Base64(bin_)}}});
    return doc.dump();
  }
  std::string Glb() const {
    json doc = doc_;
    doc["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    std::string text = doc.dump(), bin = bin_;
    while (text.size() % 4 != 0) text += ' ';
    while (bin.size() % 4 != 0) bin += '\0';
    std::string out;
    auto u32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    out += "glTF";
    u32(2);
    u32(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    u32(uint32_t(text.size()));
    out += "JSON";
    out += text;
    u32(uint32_t(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
    return out;
  }

 private:
  json doc_;
  std::string bin_;
};

// A 4x2 leaf texture with every kind of alpha, so straight (not premultiplied) storage shows.
Image8 ImportedLeafTexture() {
  Image8 image(4, 2, 4);
  const uint8_t texels[8][4] = {{200, 100, 50, 255},  {10, 220, 30, 128}, {0, 0, 0, 0},   {90, 180, 40, 1},
                                {255, 255, 255, 255}, {40, 80, 160, 64},  {5, 6, 7, 200}, {30, 200, 60, 0}};
  for (int i = 0; i < 8; ++i) std::memcpy(&image.pixels[size_t(i) * 4], texels[i], 4);
  return image;
}

// A 2x1 palette PNG whose tRNS chunk makes entry 1 transparent: how many leaf textures store
// alpha. Built by hand (stored deflate blocks) because our writer only writes RGBA.
std::string PalettePngWithTrns() {
  auto crc32 = [](const std::string& bytes) {
    uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
      crc ^= byte;
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
  };
  auto big_endian = [](uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  auto chunk = [&](const std::string& type, const std::string& data) {
    return big_endian(uint32_t(data.size())) + type + data + big_endian(crc32(type + data));
  };
  const std::string header = big_endian(2) + big_endian(1) + std::string{8, 3, 0, 0, 0};  // 8-bit palette
  const std::string palette{char(200), 100, 50, 10, char(220), 30};
  const std::string transparency{char(255), 0};
  const std::string scanline{0, 0, 1};  // filter 0, entries 0 and 1
  uint32_t a = 1, b = 0;                // Adler-32 of the raw scanline
  for (unsigned char byte : scanline) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  const std::string zlib =
      std::string{0x78, 0x01, 0x01, 3, 0, char(0xFC), char(0xFF)} + scanline + big_endian((b << 16) | a);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) + chunk("PLTE", palette) +
         chunk("tRNS", transparency) + chunk("IDAT", zlib) + chunk("IEND", "");
}

class MeshImportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / Str("voltree_mesh_import_", ::getpid(), "_",
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& name, const std::string& bytes) {
    WriteFileAtomic(dir_ / name, bytes);
    return dir_ / name;
  }
  TreeMesh Import(const fs::path& path, UpAxis up = UpAxis::kY) {
    warnings_.clear();
    TreeMesh mesh = ImportTreeMesh(path, MeshImportOptions{.up = up}, &warnings_);
    EXPECT_NO_THROW(mesh.Check());
    return mesh;
  }
  std::string ExpectErrorMentioningPath(const fs::path& path, UpAxis up = UpAxis::kY) {
    try {
      ImportTreeMesh(path, MeshImportOptions{.up = up}, &warnings_);
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
      return error.what();
    }
    ADD_FAILURE() << "no Error for " << path;
    return "";
  }

  fs::path dir_;
  std::vector<std::string> warnings_;
};

bool HasVertexAt(const TreeMesh& mesh, const Eigen::Vector3f& position) {
  for (const MeshVertex& v : mesh.vertices)
    if ((v.position - position).norm() < kTolerance) return true;
  return false;
}

const MeshVertex& VertexAt(const TreeMesh& mesh, const Eigen::Vector3f& position) {
  for (const MeshVertex& v : mesh.vertices)
    if ((v.position - position).norm() < kTolerance) return v;
  ADD_FAILURE() << "no vertex at " << position.transpose();
  return mesh.vertices.front();
}

// A y-up scene: an upward-facing ground triangle around the origin (no normals: computed), and
// one unit triangle instanced through nested TRS nodes and through a matrix node.
GltfBuilder NestedScene() {
  GltfBuilder gltf;
  const int ground = gltf.AddFloats({-1, 0, -1, 0, 0, 1, 1, 0, -1}, 3);
  const int unit = gltf.AddFloats({1, 0, 0, 0, 1, 0, 0, 0, 1}, 3);
  const int indices = gltf.AddIndices({0, 1, 2});
  const int ground_mesh = gltf.AddMesh({{"attributes", {{"POSITION", ground}}}});
  const int unit_mesh = gltf.AddMesh({{"attributes", {{"POSITION", unit}}}, {"indices", indices}});
  const float s = std::sqrt(0.5f);
  const int ground_node = gltf.AddNode({{"mesh", ground_mesh}});
  const int child = gltf.AddNode({{"mesh", unit_mesh}, {"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}});
  const int parent = gltf.AddNode({{"translation", {0, 10, 0}}, {"children", {child}}});
  const int matrix_node =
      gltf.AddNode({{"mesh", unit_mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 3, 0, 1}}});
  gltf.doc()["scenes"] = json::array({{{"nodes", {ground_node, parent, matrix_node}}}});
  gltf.doc()["scene"] = 0;
  return gltf;
}

void ExpectNestedScenePositions(const TreeMesh& mesh) {
  EXPECT_EQ(mesh.vertices.size(), 9u);
  EXPECT_EQ(mesh.TriangleCount(), 3u);
  // Ground (x, y, z) y-up -> (x, -z, y); its base centre is the origin already.
  EXPECT_TRUE(HasVertexAt(mesh, {-1, 1, 0}));
  EXPECT_TRUE(HasVertexAt(mesh, {0, -1, 0}));
  EXPECT_TRUE(HasVertexAt(mesh, {1, 1, 0}));
  EXPECT_TRUE(VertexAt(mesh, {0, -1, 0}).normal.isApprox(Eigen::Vector3f::UnitZ(), kTolerance));
  // Child: scale 2, 90 degrees about Y-up's Z, parent +10 in y: (1,0,0) -> (0,12,0) -> (0,0,12).
  EXPECT_TRUE(HasVertexAt(mesh, {0, 0, 12}));
  EXPECT_TRUE(HasVertexAt(mesh, {-2, 0, 10}));
  EXPECT_TRUE(HasVertexAt(mesh, {0, -2, 10}));
  // Matrix node, column-major translation (5, 3, 0).
  EXPECT_TRUE(HasVertexAt(mesh, {6, 0, 3}));
  EXPECT_TRUE(HasVertexAt(mesh, {5, 0, 4}));
  EXPECT_TRUE(HasVertexAt(mesh, {5, -1, 3}));
}

TEST_F(MeshImportTest, GltfEmbeddedBufferAppliesNestedTransformsAndYUp) {
  const TreeMesh mesh = Import(Write("tree.gltf", NestedScene().Gltf()));
  ExpectNestedScenePositions(mesh);
  EXPECT_TRUE(warnings_.empty());
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].alpha_mode, AlphaMode::kOpaque);
}

TEST_F(MeshImportTest, GlbMatchesGltf) {
  const TreeMesh gltf = Import(Write("tree.gltf", NestedScene().Gltf()));
  const TreeMesh glb = Import(Write("tree.glb", NestedScene().Glb()));
  ExpectNestedScenePositions(glb);
  ASSERT_EQ(glb.vertices.size(), gltf.vertices.size());
  for (size_t v = 0; v < glb.vertices.size(); ++v) EXPECT_EQ(glb.vertices[v].position, gltf.vertices[v].position);
}

TEST_F(MeshImportTest, GltfZUpOptionKeepsAxes) {
  const TreeMesh mesh = Import(Write("tree.gltf", NestedScene().Gltf()), UpAxis::kZ);
  // As stored, moved so that the lowest z (the ground's -1) is 0 and its x,y box centre is 0.
  // The lowest 2% of z in [-1, 2] holds two ground vertices at x = -1 and 1, y = 0.
  EXPECT_TRUE(HasVertexAt(mesh, {0, 0, 2}));   // ground (0, 0, 1)
  EXPECT_TRUE(HasVertexAt(mesh, {0, 12, 1}));  // child (0, 12, 0)
  EXPECT_TRUE(HasVertexAt(mesh, {6, 3, 1}));   // matrix node (6, 3, 0)
}

TEST_F(MeshImportTest, MirroringNodeKeepsComputedNormalsOutward) {
  GltfBuilder gltf;
  const int ground = gltf.AddFloats({-1, 0, -1, 0, 0, 1, 1, 0, -1}, 3);
  gltf.AddMesh({{"attributes", {{"POSITION", ground}}}});
  gltf.AddNode({{"mesh", 0}, {"scale", {-1, 1, 1}}});
  const TreeMesh mesh = Import(Write("mirror.gltf", gltf.Gltf()));
  // Without the winding flip the mirrored triangle's normal would point down (-Z).
  EXPECT_GT(VertexAt(mesh, {0, -1, 0}).normal.z(), 0.99f);
}

TEST_F(MeshImportTest, GlbMaterialsAlphaModesAndEmbeddedTexture) {
  const Image8 leaf = ImportedLeafTexture();
  WriteImage(dir_ / "leaf_source.png", leaf);
  GltfBuilder gltf;
  const int positions = gltf.AddFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3);
  const int uvs = gltf.AddFloats({0, 0, 1, 0, 0, 1}, 2);
  const int image_view = gltf.AddView(ReadFile(dir_ / "leaf_source.png"));
  gltf.doc()["images"] = json::array({{{"bufferView", image_view}, {"mimeType", "image/png"}}});
  gltf.doc()["textures"] = json::array({{{"source", 0}}});
  gltf.doc()["materials"] = json::array({{{"name", "leaf"},
                                          {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                                          {"alphaMode", "MASK"},
                                          {"alphaCutoff", 0.25},
                                          {"doubleSided", true}},
                                         {{"name", "glass"},
                                          {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.2, 1.0, 0.4}}}},
                                          {"alphaMode", "BLEND"}},
                                         {{"name", "bark"}}});
  json primitives = json::array();
  for (int m = 0; m < 3; ++m)
    primitives.push_back({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", m}});
  gltf.doc()["meshes"] = json::array({{{"primitives", primitives}}});
  gltf.AddNode({{"mesh", 0}});

  const TreeMesh mesh = Import(Write("leaf.glb", gltf.Glb()));
  ASSERT_EQ(mesh.materials.size(), 3u);
  ASSERT_EQ(mesh.groups.size(), 3u);
  const Material& leaf_material = mesh.materials[0];
  EXPECT_EQ(leaf_material.name, "leaf");
  EXPECT_EQ(leaf_material.alpha_mode, AlphaMode::kMask);
  EXPECT_FLOAT_EQ(leaf_material.alpha_cutoff, 0.25f);
  EXPECT_TRUE(leaf_material.double_sided);
  ASSERT_EQ(leaf_material.texture, 0);
  EXPECT_EQ(mesh.textures[0], leaf);  // exact: straight alpha, sRGB bytes as stored
  const Material& glass = mesh.materials[1];
  EXPECT_EQ(glass.alpha_mode, AlphaMode::kBlend);
  EXPECT_FALSE(glass.double_sided);
  EXPECT_EQ(glass.texture, -1);
  // Linear factors become sRGB: 0.5 -> 0.7354, 0.2 -> 0.4845 (IEC 61966-2-1).
  EXPECT_NEAR(glass.base_color.x(), 0.7354f, 1e-3f);
  EXPECT_NEAR(glass.base_color.y(), 0.4845f, 1e-3f);
  EXPECT_NEAR(glass.base_color.z(), 1.0f, 1e-6f);
  EXPECT_NEAR(glass.base_color.w(), 0.4f, 1e-6f);
  EXPECT_EQ(mesh.materials[2].alpha_mode, AlphaMode::kOpaque);
  EXPECT_EQ(mesh.vertices[1].uv, Eigen::Vector2f(1, 0));
}

TEST_F(MeshImportTest, GltfDataUriImageAndMissingExternalImage) {
  WriteImage(dir_ / "leaf_source.png", ImportedLeafTexture());
  GltfBuilder gltf;
  const int positions = gltf.AddFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3);
  gltf.doc()["images"] = json::array({{{"uri", "data:image/png;base64," + Base64(ReadFile(dir_ / "leaf_source.png"))}},
                                      {{"uri", "missing%20leaf.png"}},
                                      {{"uri", "leaf%20source.png"}}});
  fs::rename(dir_ / "leaf_source.png", dir_ / "leaf source.png");  // external, percent-encoded name
  gltf.doc()["textures"] = json::array({{{"source", 0}}, {{"source", 1}}, {{"source", 2}}});
  gltf.doc()["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
                                         {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}},
                                         {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}}});
  gltf.doc()["meshes"] = json::array({{{"primitives",
                                        {{{"attributes", {{"POSITION", positions}}}, {"material", 0}},
                                         {{"attributes", {{"POSITION", positions}}}, {"material", 1}},
                                         {{"attributes", {{"POSITION", positions}}}, {"material", 2}}}}}});
  gltf.AddNode({{"mesh", 0}});
  const fs::path path = Write("tree.gltf", gltf.Gltf());
  const TreeMesh mesh = Import(path);
  ASSERT_EQ(mesh.textures.size(), 2u);
  EXPECT_EQ(mesh.textures[0], ImportedLeafTexture());
  EXPECT_EQ(mesh.textures[1], ImportedLeafTexture());
  ASSERT_EQ(mesh.materials.size(), 3u);
  EXPECT_EQ(mesh.materials[1].texture, -1);
  EXPECT_EQ(mesh.materials[2].texture, 1);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_EQ(warnings_[0], path.string() + ": texture 'missing%20leaf.png' not found; using a flat colour");
}

TEST_F(MeshImportTest, GltfOutOfRangeIndexIsAnError) {
  GltfBuilder gltf;
  const int positions = gltf.AddFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3);
  gltf.AddMesh({{"attributes", {{"POSITION", positions}}}, {"indices", gltf.AddIndices({0, 1, 3})}});
  gltf.AddNode({{"mesh", 0}});
  const std::string message = ExpectErrorMentioningPath(Write("bad.gltf", gltf.Gltf()));
  EXPECT_NE(message.find("index 3"), std::string::npos) << message;
}

TEST_F(MeshImportTest, GltfAccessorPastItsBufferIsAnError) {
  GltfBuilder gltf;
  const int positions = gltf.AddFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3);
  gltf.doc()["accessors"][positions]["count"] = 4;  // 48 bytes from a 36-byte view
  gltf.AddMesh({{"attributes", {{"POSITION", positions}}}});
  gltf.AddNode({{"mesh", 0}});
  const std::string message = ExpectErrorMentioningPath(Write("short.glb", gltf.Glb()));
  EXPECT_NE(message.find("runs past the end"), std::string::npos) << message;
}

TEST_F(MeshImportTest, GltfNodeCycleIsSkippedWithAWarning) {
  GltfBuilder gltf = NestedScene();
  gltf.doc()["nodes"][1]["children"] = {2};  // child -> parent -> child ...
  const TreeMesh mesh = Import(Write("cycle.gltf", gltf.Gltf()));
  ExpectNestedScenePositions(mesh);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_NE(warnings_[0].find("node 2 is reached twice"), std::string::npos) << warnings_[0];
}

TEST_F(MeshImportTest, GltfRequiringDracoIsAnError) {
  GltfBuilder gltf = NestedScene();
  gltf.doc()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  gltf.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  const std::string message = ExpectErrorMentioningPath(Write("draco.gltf", gltf.Gltf()));
  EXPECT_NE(message.find("KHR_draco_mesh_compression"), std::string::npos) << message;
}

// A z-up OBJ: a thin trunk square around (5, 5) and a crown reaching far to +x, so the origin
// must come from the lowest vertices, not from the whole bounding box.
constexpr const char* kTrunkObj =
    "v 4.9 4.9 0\nv 5.1 4.9 0\nv 5.1 5.1 0\nv 4.9 5.1 0\n"
    "v 5 5 10\nv 25 5 10\nv 25 8 12\n"
    "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 5 6 7\n";

TEST_F(MeshImportTest, ObjZUpOriginAtTrunkBase) {
  const TreeMesh mesh = Import(Write("trunk.obj", kTrunkObj), UpAxis::kZ);
  EXPECT_EQ(mesh.vertices.size(), 7u);
  EXPECT_EQ(mesh.TriangleCount(), 5u);
  EXPECT_TRUE(HasVertexAt(mesh, {-0.1f, -0.1f, 0}));
  EXPECT_TRUE(HasVertexAt(mesh, {0, 0, 10}));
  EXPECT_TRUE(HasVertexAt(mesh, {20, 3, 12}));
  const auto [lo, hi] = mesh.Bounds();
  EXPECT_NEAR(lo.z(), 0, kTolerance);
  EXPECT_NEAR(hi.z(), 12, kTolerance);
  // The material-less OBJ gets one default material; the normals were computed.
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_NEAR(VertexAt(mesh, {0, 0, 10}).normal.norm(), 1.0f, kTolerance);
}

TEST_F(MeshImportTest, ObjYUpRotatesToZUp) {
  // The same trunk written y-up: (x, y, z)_zup = (x, -z, y)_yup, i.e. file (x, z_up, -y_up).
  const std::string obj =
      "v 4.9 0 -4.9\nv 5.1 0 -4.9\nv 5.1 0 -5.1\nv 4.9 0 -5.1\n"
      "v 5 10 -5\nv 25 10 -5\nv 25 12 -8\n"
      "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 5 6 7\n";
  const TreeMesh yup = Import(Write("yup.obj", obj), UpAxis::kY);
  const TreeMesh zup = Import(Write("zup.obj", kTrunkObj), UpAxis::kZ);
  ASSERT_EQ(yup.vertices.size(), zup.vertices.size());
  for (size_t v = 0; v < yup.vertices.size(); ++v) {
    EXPECT_LT((yup.vertices[v].position - zup.vertices[v].position).norm(), kTolerance)
        << v << ": " << yup.vertices[v].position.transpose() << " vs " << zup.vertices[v].position.transpose();
    EXPECT_LT((yup.vertices[v].normal - zup.vertices[v].normal).norm(), kTolerance) << v;
  }
}

TEST_F(MeshImportTest, ObjLeafTextureWithAlphaBecomesMaskedDoubleSided) {
  WriteImage(dir_ / "leaf.png", ImportedLeafTexture());
  Write("tree.mtl", "newmtl bark\nKd 0.4 0.3 0.2\nnewmtl leaf\nKd 0.8 0.8 0.8\nmap_Kd leaf.png\n");
  const fs::path path = Write("tree.obj",
                              "mtllib tree.mtl\n"
                              "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 0 2\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                              "vn 0 -1 0\n"
                              "usemtl bark\nf 1 2 5\n"
                              "usemtl leaf\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
  const TreeMesh mesh = Import(path, UpAxis::kZ);
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
  ASSERT_EQ(mesh.materials.size(), 2u);
  ASSERT_EQ(mesh.groups.size(), 2u);
  EXPECT_EQ(mesh.groups[1].indices.size(), 6u);  // the quad, triangulated
  const Material& bark = mesh.materials[0];
  EXPECT_EQ(bark.alpha_mode, AlphaMode::kOpaque);
  EXPECT_FALSE(bark.double_sided);
  EXPECT_TRUE(bark.base_color.isApprox(Eigen::Vector4f(0.4f, 0.3f, 0.2f, 1.0f)));
  const Material& leaf = mesh.materials[1];
  EXPECT_EQ(leaf.alpha_mode, AlphaMode::kMask);
  EXPECT_TRUE(leaf.double_sided);
  ASSERT_EQ(leaf.texture, 0);
  EXPECT_EQ(mesh.textures[0], ImportedLeafTexture());
  EXPECT_EQ(leaf.base_color, Eigen::Vector4f::Ones());  // the texture replaces Kd
  // vt (0, 0) is OBJ's bottom-left; ours counts rows from the top.
  const MeshVertex& corner = mesh.vertices[mesh.groups[1].indices[0]];
  EXPECT_EQ(corner.uv, Eigen::Vector2f(0, 1));
  EXPECT_EQ(corner.normal, Eigen::Vector3f(0, -1, 0));
}

TEST_F(MeshImportTest, ObjMapDMultipliesAlpha) {
  Image8 colour(2, 2, 3, 0);  // RGB, no alpha of its own
  for (size_t i = 0; i < colour.pixels.size(); ++i) colour.pixels[i] = uint8_t(10 * i);
  Image8 grey(2, 2, 1);
  grey.pixels = {255, 0, 128, 64};
  Image8 rgba_mask(2, 2, 4, 77);  // an RGBA alpha map: its alpha channel is the coverage
  for (int i = 0; i < 4; ++i) rgba_mask.pixels[size_t(i) * 4 + 3] = uint8_t(i * 50);
  WriteImage(dir_ / "colour.png", colour);
  WriteImage(dir_ / "grey.png", grey);
  WriteImage(dir_ / "mask.png", rgba_mask);
  Write("tree.mtl",
        "newmtl a\nmap_Kd colour.png\nmap_d grey.png\n"
        "newmtl b\nKd 0.1 0.5 0.2\nmap_d mask.png\n"
        "newmtl c\nmap_Kd wide.png\nmap_d narrow.png\n");
  Image8 narrow(2, 1, 1);
  narrow.pixels = {0, 255};
  WriteImage(dir_ / "wide.png", Image8(4, 1, 3, 90));
  WriteImage(dir_ / "narrow.png", narrow);
  const TreeMesh mesh = Import(Write("tree.obj",
                                     "mtllib tree.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\n"
                                     "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\nusemtl c\nf 2 1 3\n"),
                               UpAxis::kZ);
  ASSERT_EQ(mesh.materials.size(), 3u);
  // A map_d of another size is resampled bilinearly, texel centres on texel centres: the 4
  // texels sit at 2-texel-map coordinates -0.25 (clamped), 0.25, 0.75, 1.25 (clamped).
  const Image8& texture_c = mesh.textures.at(mesh.materials[2].texture);
  ASSERT_EQ(texture_c.width, 4);
  const uint8_t expected_c[4] = {0, 64, 191, 255};
  for (int x = 0; x < 4; ++x) EXPECT_EQ(texture_c.at(x, 0, 3), expected_c[x]) << x;
  const Material& a = mesh.materials[0];
  EXPECT_EQ(a.alpha_mode, AlphaMode::kMask);
  EXPECT_TRUE(a.double_sided);
  const Image8& texture_a = mesh.textures.at(a.texture);
  ASSERT_EQ(texture_a.channels, 4);
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(texture_a.pixels[i * 4 + c], colour.pixels[i * 3 + c]);
    EXPECT_EQ(texture_a.pixels[i * 4 + 3], grey.pixels[i]);
  }
  const Material& b = mesh.materials[1];
  EXPECT_EQ(b.alpha_mode, AlphaMode::kMask);
  EXPECT_TRUE(b.base_color.isApprox(Eigen::Vector4f(0.1f, 0.5f, 0.2f, 1.0f)));  // no map_Kd: Kd stays
  const Image8& texture_b = mesh.textures.at(b.texture);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(texture_b.pixels[i * 4], 255);  // white, tinted by Kd
    EXPECT_EQ(texture_b.pixels[i * 4 + 3], i * 50);
  }
}

TEST_F(MeshImportTest, ObjPaletteTextureWithTrnsAlphaBecomesMask) {
  Write("leaf.png", PalettePngWithTrns());
  Write("tree.mtl", "newmtl leaf\nmap_Kd leaf.png\n");
  const TreeMesh mesh = Import(Write("tree.obj", "mtllib tree.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\nusemtl leaf\nf 1 2 3\n"));
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].alpha_mode, AlphaMode::kMask);
  ASSERT_EQ(mesh.materials[0].texture, 0);
  const Image8& texture = mesh.textures[0];
  ASSERT_EQ(texture.channels, 4);
  EXPECT_EQ(texture.pixels, (std::vector<uint8_t>{200, 100, 50, 255, 10, 220, 30, 0}));
}

TEST_F(MeshImportTest, ObjMissingTextureWarnsAndUsesFlatColour) {
  Write("tree.mtl", "newmtl leaf\nKd 0.2 0.6 0.1\nd 0.5\nmap_Kd leaf.png\n");
  const fs::path path = Write("tree.obj", "mtllib tree.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\nusemtl leaf\nf 1 2 3\n");
  const TreeMesh mesh = Import(path, UpAxis::kZ);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_EQ(warnings_[0], path.string() + ": texture 'leaf.png' not found; using a flat colour");
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].texture, -1);
  EXPECT_TRUE(mesh.materials[0].base_color.isApprox(Eigen::Vector4f(0.2f, 0.6f, 0.1f, 0.5f)));
  EXPECT_EQ(mesh.materials[0].alpha_mode, AlphaMode::kBlend);  // d < 1
  EXPECT_TRUE(mesh.textures.empty());
}

TEST_F(MeshImportTest, ObjOutOfRangeIndexIsAnError) {
  const fs::path path = Write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 9\n");
  ExpectErrorMentioningPath(path);
}

// tinyobjloader reads these as 0; the importer names the line instead.
TEST_F(MeshImportTest, ObjCoordinateThatIsNotAFiniteNumberIsAnError) {
  for (const char* bad : {"nan", "-inf", "1,5", "1e999"}) {
    const std::string message =
        ExpectErrorMentioningPath(Write("bad.obj", Str("v 0 0 0\nv 1 0 0\nv 0 ", bad, " 1\nf 1 2 3\n")));
    EXPECT_NE(message.find("bad.obj:3: vertex 3 has a coordinate '" + std::string(bad) + "'"), std::string::npos)
        << message;
  }
  // Windows line endings, tabs, a w component and a comment are still numbers.
  const TreeMesh mesh = Import(Write("crlf.obj", "v 0 0 0 1\r\nv\t1 0 0 # x\r\nv 0 0 1\r\nf 1 2 3\r\n"));
  EXPECT_EQ(mesh.TriangleCount(), 1u);
}

TEST_F(MeshImportTest, BadFilesAreErrorsNamingThePath) {
  ExpectErrorMentioningPath(dir_ / "absent.gltf");
  ExpectErrorMentioningPath(Write("empty.gltf", ""));
  ExpectErrorMentioningPath(Write("garbage.gltf", "{ this is not json"));
  ExpectErrorMentioningPath(Write("garbage.glb", "glTF\x02\x00\x00\x00 truncated"));
  const std::string no_faces = ExpectErrorMentioningPath(Write("garbage.obj", "hello world\nv 1 2 3\n"));
  EXPECT_NE(no_faces.find("no triangles"), std::string::npos) << no_faces;
  ExpectErrorMentioningPath(Write("empty.obj", ""));
  const std::string unsupported = ExpectErrorMentioningPath(Write("tree.fbx", "x"));
  EXPECT_NE(unsupported.find(".gltf, .glb, .obj"), std::string::npos) << unsupported;
  GltfBuilder lines;  // a glTF with only a line primitive has no triangles
  lines.AddMesh({{"attributes", {{"POSITION", lines.AddFloats({0, 0, 0, 1, 0, 0}, 3)}}}, {"mode", 1}});
  lines.AddNode({{"mesh", 0}});
  const std::string only_lines = ExpectErrorMentioningPath(Write("lines.gltf", lines.Gltf()));
  EXPECT_NE(only_lines.find("no triangles"), std::string::npos) << only_lines;
}

TEST_F(MeshImportTest, SameFileGivesIdenticalMeshes) {
  WriteImage(dir_ / "leaf.png", ImportedLeafTexture());
  Write("tree.mtl", "newmtl leaf\nmap_Kd leaf.png\n");
  const fs::path path = Write("tree.obj", std::string("mtllib tree.mtl\nusemtl leaf\n") + kTrunkObj);
  const TreeMesh first = Import(path), second = Import(path);
  ASSERT_EQ(first.vertices.size(), second.vertices.size());
  for (size_t v = 0; v < first.vertices.size(); ++v) {
    EXPECT_EQ(first.vertices[v].position, second.vertices[v].position);
    EXPECT_EQ(first.vertices[v].normal, second.vertices[v].normal);
  }
  ASSERT_EQ(first.groups.size(), second.groups.size());
  EXPECT_EQ(first.groups[0].indices, second.groups[0].indices);
  EXPECT_EQ(first.textures, second.textures);
}

TEST(UpAxisFromName, ParsesBothCases) {
  EXPECT_EQ(UpAxisFromName("Y"), UpAxis::kY);
  EXPECT_EQ(UpAxisFromName("z"), UpAxis::kZ);
  EXPECT_FALSE(UpAxisFromName("x").has_value());
}

}  // namespace
}  // namespace voltree
