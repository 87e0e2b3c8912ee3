// TreeMesh::Check refuses what would poison every later stage.
#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"
#include "samples/tree_mesh.h"

namespace voltree {
namespace {

TreeMesh OneTriangle() {
  TreeMesh mesh;
  mesh.materials.resize(1);
  mesh.vertices.resize(3);
  mesh.vertices[1].position = Eigen::Vector3f(1, 0, 0);
  mesh.vertices[2].position = Eigen::Vector3f(0, 0, 1);
  mesh.groups.push_back(MeshGroup{0, {0, 1, 2}});
  return mesh;
}

TEST(TreeMesh, NonFiniteVertexIsNamed) {
  TreeMesh mesh = OneTriangle();
  EXPECT_NO_THROW(mesh.Check());
  mesh.vertices[2].position.y() = std::numeric_limits<float>::quiet_NaN();
  try {
    mesh.Check();
    FAIL() << "a NaN vertex was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("mesh vertex 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace voltree
