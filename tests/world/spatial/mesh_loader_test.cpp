#include "amp/world/mesh_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "amp/core/error.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

const std::string kMeshes = std::string(AMP_SOURCE_DIR) + "/tests/data/meshes/";

void expect_bounds(const TriangleMesh& m, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::AlignedBox3d b = mesh_bounds(m);
  EXPECT_TRUE(b.min().isApprox(lo, 1e-9)) << b.min().transpose();
  EXPECT_TRUE(b.max().isApprox(hi, 1e-9)) << b.max().transpose();
}

TEST(MeshLoader, ObjQuadsAreTriangulated) {
  const TriangleMesh m = load_mesh(kMeshes + "box.obj");
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  expect_bounds(m, {0, 0, 0}, {2, 1, 0.5});
}

// assimp 5.2 read "tests/data/meshes/../../data/meshes/box.obj"-like paths (".." after folders) as
// "File read error": an experiment beside the repository names the shared data that way.
TEST(MeshLoader, PathsWithParentSegmentsLoad) {
  const std::filesystem::path roundabout =
      std::filesystem::path(AMP_SOURCE_DIR) / "tests/data/meshes/../../../tests/data/meshes/box.obj";
  const TriangleMesh m = load_mesh(roundabout.string());
  EXPECT_EQ(m.triangles.size(), 12u);
}

TEST(MeshLoader, StlVerticesAreJoined) {
  const TriangleMesh m = load_mesh(kMeshes + "tetra.stl");
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 4u);
  expect_bounds(m, {0, 0, 0}, {1, 1, 1});
}

TEST(MeshLoader, Ply) {
  const TriangleMesh m = load_mesh(kMeshes + "tetra.ply");
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 4u);
  expect_bounds(m, {0, 0, 0}, {3, 3, 3});
  EXPECT_TRUE(vertex_mean(m).isApprox(Eigen::Vector3d(0.75, 0.75, 0.75)));
}

TEST(MeshLoader, ColladaNodeTransformsAndYUpAreApplied) {
  // Box x 2, up 3, depth 1 under nested nodes translating by (10, 0, 0) and 5 upwards (Y-up file).
  const TriangleMesh m = load_mesh(kMeshes + "box_yup.dae");
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  expect_bounds(m, {10, -1, 5}, {12, 0, 8});
}

TEST(MeshLoader, ExplicitUpAxisOverridesTheFile) {
  expect_bounds(load_mesh(kMeshes + "box_yup.dae", UpAxis::kZ), {10, 5, 0}, {12, 8, 1});
  expect_bounds(load_mesh(kMeshes + "box.obj", UpAxis::kY), {0, -0.5, 0}, {2, 0, 1});
}

TEST(MeshLoader, TrianglesKeepTheirOrientationUnderYUp) {
  // A proper rotation keeps outward normals outward: the signed volume stays positive.
  const TriangleMesh m = load_mesh(kMeshes + "box_yup.dae");
  double volume = 0.0;
  for (const Eigen::Vector3i& t : m.triangles) {
    volume += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  }
  EXPECT_NEAR(volume, 6.0, 1e-9);
}

TEST(MeshLoader, UnreadableFileNamesTheFile) {
  try {
    load_mesh(kMeshes + "not_a_mesh.stl");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_mesh.stl"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_mesh(kMeshes + "missing.obj"), FileError);
}

// Fuzzing found: one character that is not a digit in a COLLADA <p> list sent assimp 5.2 into growing
// its index buffer until std::bad_alloc (minutes). load_mesh refuses such a file at once.
TEST(MeshLoader, ColladaIndexListWithAForeignCharacterIsRefused) {
  std::ifstream in(kMeshes + "box_yup.dae");
  std::stringstream text;
  text << in.rdbuf();
  std::string doc = text.str();
  const std::size_t p = doc.find("<p>");
  ASSERT_NE(p, std::string::npos);
  doc.insert(p + 3, "7 \xff");
  const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "foreign_index.dae";
  std::ofstream(file, std::ios::binary) << doc;
  try {
    load_mesh(file);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("foreign_index.dae: cannot read mesh: a COLLADA index list holds '\\xff"),
              std::string::npos) << e.what();
  }
}

// Fuzzing found (corpus/mesh_dae/finding-accessor-past-its-array.dae): a <float_array> without its
// count attribute is stored empty by assimp 5.2, which then reads the positions of its <accessor>
// through a null pointer. Any accessor reaching past its array is refused before assimp sees it.
TEST(MeshLoader, ColladaAccessorPastItsArrayIsRefused) {
  std::ifstream in(kMeshes + "box_yup.dae");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string array_count = "count=\"24\"";
  ASSERT_NE(doc.find(array_count), std::string::npos);
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& needle) {
    std::string bad = doc;
    bad.replace(bad.find(from), from.size(), to);
    const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "accessor.dae";
    std::ofstream(file, std::ios::binary) << bad;
    try {
      load_mesh(file);
      ADD_FAILURE() << "expected FileError for " << to;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("accessor.dae: cannot read mesh: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  refused(array_count, "count2=\"24\"", "a COLLADA <accessor> of 8 x 3 from offset 0 reads past '#box-positions-array' of 0");
  refused(array_count, "count=\"23\"", "reads past '#box-positions-array' of 23");
  refused(array_count, "count=\"2&#52;\"", "the count of COLLADA <float_array> is not a plain number");
  refused("source=\"#box-positions-array\"", "source=\"#elsewhere\"", "source '#elsewhere' names no data array");
  refused("stride=\"3\"", "stride=\"3\" offset=\"1\"", "a COLLADA <accessor> of 8 x 3 from offset 1 reads past");
  refused("stride=\"3\"", "stride=\"2\"", "a COLLADA <accessor> has 3 params in a stride of 2");
  EXPECT_EQ(load_mesh(kMeshes + "box_yup.dae").vertices.size(), 8U);
}

TEST(MeshLoader, ParsesUpAxis) {
  EXPECT_EQ(parse_up_axis("y"), UpAxis::kY);
  EXPECT_EQ(parse_up_axis("z"), UpAxis::kZ);
  EXPECT_THROW(parse_up_axis("x"), ParameterError);
}

}  // namespace
}  // namespace amp::world
