#include "amp/world/spatial_yaml.hpp"

#include <gtest/gtest.h>

#include <string>

#include "amp/core/error.hpp"
#include "amp/world/spatial_environment.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

// Parsed as if it were a file in tests/data/meshes, so that mesh paths resolve there.
LoadedWorld parse(const std::string& text) {
  const std::filesystem::path file = std::filesystem::path(AMP_SOURCE_DIR) / "tests/data/meshes/problem.yaml";
  return parse_spatial_world(YamlFields(YAML::Load(text), file, ""));
}

const std::string kWorld = R"(
bounds: {min: [0, 0, 0], max: [10, 10, 5]}
resolution: 0.02
world:
  obstacles:
    - box: {center: [5, 5, 1], size: [2, 2, 2], rotation: [0, 0, 0.3826834, 0.9238795]}
    - sphere: {center: [2, 2, 2], radius: 0.5}
    - cylinder: {center: [8, 2, 2], radius: 0.5, length: 2}
    - mesh: {file: box.obj, position: [1, 7, 0], scale: 2.0, up: z}
)";

TEST(SpatialYaml, RigidBodyInSe3) {
  const LoadedWorld w = parse(kWorld + "robot: {type: rigid3d, shapes: [{box: {center: [0, 0, 0], size: [1, 0.2, 0.2]}}]}\n");
  ASSERT_EQ(w.space->kind(), "se3");
  const auto& env = dynamic_cast<const SpatialEnvironment&>(*w.environment);
  ASSERT_EQ(env.world().obstacles().size(), 4u);
  EXPECT_EQ(env.world().obstacles()[3].kind, Solid::Kind::kMesh);
  // The scaled mesh: box.obj is 2 x 1 x 0.5, doubled, placed at (1, 7, 0).
  const Eigen::AlignedBox3d mb = env.world().obstacles()[3].bounds();
  EXPECT_TRUE(mb.max().isApprox(Eigen::Vector3d(5, 9, 1)));
  EXPECT_NEAR(w.space->resolution(), 0.02 * w.space->maximum_extent(), 1e-12);
  EXPECT_NEAR(env.robot_radius(), std::sqrt(0.25 + 0.01 + 0.01), 1e-12);
  core::Counters counters;
  auto checker = env.make_checker(counters);
  State s(7);
  s << 5, 5, 3, 0, 0, 0, 1;
  EXPECT_TRUE(checker->is_valid(s));
  s[2] = 1.5;  // inside the turned box
  EXPECT_FALSE(checker->is_valid(s));
  s << 5, 8.5, 0.6, 0, 0, 0, 1;  // across the mesh's face x = 5
  EXPECT_FALSE(checker->is_valid(s));
  s << 3, 8.5, 0.6, 0, 0, 0, 1;  // wholly inside: meshes are surfaces to FCL (as in OMPL.app)
  EXPECT_TRUE(checker->is_valid(s));
}

TEST(SpatialYaml, SphereInR3) {
  const LoadedWorld w = parse(kWorld + "robot: {type: sphere, radius: 0.25}\n");
  EXPECT_EQ(w.space->kind(), "rn");
  EXPECT_EQ(w.space->dimension(), 3);
  EXPECT_DOUBLE_EQ(w.environment->robot_min_diameter(), 0.5);
}

TEST(SpatialYaml, ScaraLinkage) {
  const LoadedWorld w = parse(kWorld + R"(robot:
  type: scara
  base: [5, 1, 0]
  column_height: 3
  upper_arm: 1.5
  forearm: 1.0
  link_radius: 0.1
  slide: [0.5, 2.5]
  limits: [[-3, 3], [-2, 2], [-2.5, 2.5], [-3, 3]]
  tool: [{box: {center: [0, 0, -0.2], size: [0.1, 0.1, 0.4]}}]
)");
  ASSERT_EQ(w.space->kind(), "linkage");
  EXPECT_EQ(w.space->dimension(), 5);
  State s(5);
  s << 0, 1.0, 0, 0, 0;
  // Tip: column at (5, 1), reach 2.5 along x, 1.0 up, wrist 0.2 (default 2 r), tool 0.4 below.
  EXPECT_TRUE(w.environment->reference_point(s).isApprox(Eigen::Vector3d(7.5, 1, 0.4)));
}

TEST(SpatialYaml, ErrorsNameTheField) {
  auto expect_error = [](const std::string& text, const std::string& needle) {
    try {
      parse(text);
      ADD_FAILURE() << "expected FileError for " << needle;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error(kWorld + "robot: {type: car}\n", "type");
  expect_error(kWorld + "robot: {type: sphere, radius: -1}\n", "radius");
  expect_error("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\nworld: {obstacles: [{cone: {}}]}\nrobot: {type: sphere, radius: 1}\n",
               "cone");
  expect_error("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\nworld: {obstacles: [{mesh: {file: none.obj}}]}\n"
               "robot: {type: sphere, radius: 1}\n", "none.obj");
  // A file name longer than the OS allows is "no such file" too, not std::filesystem's exception.
  expect_error("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\nworld: {obstacles: [{mesh: {file: " + std::string(300, 'm') +
               ".obj}}]}\nrobot: {type: sphere, radius: 1}\n", "no such file");
  expect_error("bounds: {min: [0, 0, 0], max: [1, 0, 1]}\nrobot: {type: sphere, radius: 1}\n", "bounds");
  expect_error(kWorld + "robot: {type: scara, base: [0, 0, 0], column_height: 1, upper_arm: 1, forearm: 1, "
                        "link_radius: 0.1, slide: [0, 2], limits: [[-1, 1], [-1, 1], [-1, 1], [-1, 1]], "
                        "tool: [{box: {center: [0, 0, 0], size: [0.1, 0.1, 0.1]}}]}\n",
               "slide");
}

// Fuzzing (corpus/problem_yaml/solid-key-not-a-scalar.yaml): an obstacle whose one key is itself a mapping
// let yaml-cpp's TypedBadConversion escape instead of a FileError.
TEST(SpatialYaml, SolidKeyNotAScalarIsAFileError) {
  const std::string head = "bounds: {min: [0, 0, 0], max: [1, 1, 1]}\nrobot: {type: sphere, radius: 0.1}\n";
  for (const std::string obstacle : {"{box: {center: [0, 0, 0], size: [1, 1, 1]}}: ", "? [box, sphere]\n      : 1"}) {
    try {
      parse(head + "world:\n  obstacles:\n    - " + obstacle + "\n");
      ADD_FAILURE() << "expected FileError for " << obstacle;
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("non-scalar key"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace amp::world
