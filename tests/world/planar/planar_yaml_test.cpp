#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/planar_yaml.hpp"

namespace amp::world {
namespace {

LoadedWorld parse(const std::string& text) { return parse_planar_world(YamlFields(YAML::Load(text), "p.yaml", "")); }

// The FileError message of parsing `text` ("" if it parses).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

const PlanarEnvironment& planar(const LoadedWorld& w) { return dynamic_cast<const PlanarEnvironment&>(*w.environment); }

constexpr const char* kRigid = R"(
name: demo
start: [1, 1, 0]
goal: [9, 9, 0]
defaults: {planner: prm}
bounds: {min: [0, 0], max: [10, 10]}
resolution: 0.02
world:
  obstacles:
    - polygon: [[4, 4], [6, 4], [5, 6]]
    - circle: {center: [2, 8], radius: 0.5}
    - rectangle: {center: [8, 2], size: [2, 1], angle: 1.5707963267948966}
robot:
  type: rigid2d
  shapes:
    - rectangle: {center: [0, 0], size: [1, 0.4]}
    - circle: {center: [0.5, 0], radius: 0.2}
)";

TEST(PlanarYaml, RigidRobotWorldAndSe2Space) {
  const LoadedWorld w = parse(kRigid);
  const PlanarEnvironment& env = planar(w);
  EXPECT_EQ(env.world().obstacles().polygons.size(), 2u);
  EXPECT_EQ(env.world().obstacles().circles.size(), 1u);
  // The rotated rectangle is 1 wide in x and 2 tall in y.
  const auto& r = env.world().obstacles().polygons[1].vertices;
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const auto& v : r) xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x()), ymin = std::min(ymin, v.y()), ymax = std::max(ymax, v.y());
  EXPECT_NEAR(xmax - xmin, 1.0, 1e-12);
  EXPECT_NEAR(ymax - ymin, 2.0, 1e-12);
  EXPECT_EQ(env.robot().kind(), PlanarRobot::Kind::kRigid);
  EXPECT_NEAR(env.robot_radius(), 0.7, 1e-12);
  EXPECT_EQ(w.space->kind(), "se2");
  EXPECT_EQ(w.space->dimension(), 3);
  const auto& js = dynamic_cast<const core::JointSpace&>(*w.space);
  EXPECT_NEAR(js.joints()[2].weight, 0.7, 1e-12);
  EXPECT_NEAR(w.space->resolution(), 0.02 * w.space->maximum_extent(), 1e-12);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  State s(3);
  s << 1, 1, 0;
  EXPECT_TRUE(checker->is_valid(s));
  s << 5, 4.5, 0;
  EXPECT_FALSE(checker->is_valid(s));
}

TEST(PlanarYaml, DiscAndPointRobotsUseRn) {
  const LoadedWorld disc = parse("bounds: {min: [0, 0], max: [4, 3]}\nworld: {}\nrobot: {type: disc, radius: 0.25}\n");
  EXPECT_EQ(disc.space->kind(), "rn");
  EXPECT_EQ(disc.space->dimension(), 2);
  EXPECT_DOUBLE_EQ(disc.environment->robot_min_diameter(), 0.5);
  EXPECT_NEAR(disc.space->resolution(), 0.01 * 5.0, 1e-12);  // default fraction of the diagonal
  const LoadedWorld point = parse("bounds: {min: [0, 0], max: [4, 3]}\nworld: {obstacles: []}\nrobot: {type: point}\n");
  EXPECT_EQ(planar(point).robot().links()[0].circles[0].radius, 0.0);
}

TEST(PlanarYaml, ArmAndLinkageJoints) {
  const LoadedWorld arm = parse(R"(
bounds: {min: [0, 0], max: [10, 10]}
world: {obstacles: []}
robot: {type: arm, base: [5, 5, 0], links: [{length: 2, width: 0.2}, {length: 1, width: 0.2}], limits: [[-1, 1], [-2, 2]]}
)");
  const auto& a = dynamic_cast<const core::JointSpace&>(*arm.space);
  EXPECT_EQ(a.kind(), "linkage");
  ASSERT_EQ(a.dimension(), 2);
  EXPECT_EQ(a.joints()[0].kind, core::JointKind::kRevolute);
  EXPECT_EQ(a.joints()[1].hi, 2.0);
  EXPECT_DOUBLE_EQ(a.joints()[0].weight, 3.0);  // reach beyond the joint
  EXPECT_DOUBLE_EQ(a.joints()[1].weight, 1.0);
  const LoadedWorld chain = parse(R"(
bounds: {min: [0, 0], max: [10, 10]}
world: {}
robot: {type: linkage, links: [{length: 1, width: 0.2}, {length: 1, width: 0.2}, {length: 1, width: 0.2}]}
)");
  const auto& c = dynamic_cast<const core::JointSpace&>(*chain.space);
  ASSERT_EQ(c.dimension(), 5);
  EXPECT_EQ(c.joints()[0].kind, core::JointKind::kLinear);
  EXPECT_EQ(c.joints()[2].kind, core::JointKind::kContinuous);
  EXPECT_EQ(c.joints()[4].kind, core::JointKind::kContinuous);
  EXPECT_EQ(planar(chain).robot().state_dimension(), 5);
}

TEST(PlanarYaml, ErrorsNameTheFileAndField) {
  const std::string base = "bounds: {min: [0, 0], max: [10, 10]}\nrobot: {type: disc, radius: 1}\n";
  auto contains = [](const std::string& msg, const std::string& part) {
    return msg.find(part) != std::string::npos ? ::testing::AssertionSuccess()
                                               : ::testing::AssertionFailure() << "'" << msg << "' lacks '" << part << "'";
  };
  EXPECT_TRUE(contains(error_of(base + "world: {obstacles: [{circle: {center: [1, 1], radius: 1}}, "
                                       "{polygon: [[0, 0], [1, 1], [1, 0], [0, 1]]}]}\n"),
                       "p.yaml: world.obstacles[1].polygon: self-intersecting"));
  EXPECT_TRUE(contains(error_of(base + "world: {obstacles: [{circle: {center: [1, 1], radius: -1}}]}\n"),
                       "world.obstacles[0].circle.radius"));
  EXPECT_TRUE(contains(error_of(base + "world: {obstacles: [{box: {}}]}\n"), "world.obstacles[0].box"));
  EXPECT_TRUE(contains(error_of(base + "world: {}\ncolour: red\n"), "colour"));
  EXPECT_TRUE(contains(error_of(base + "world: {walls: []}\n"), "world.walls"));
  EXPECT_TRUE(contains(error_of("bounds: {min: [0, 0], max: [0, 10]}\nworld: {}\nrobot: {type: point}\n"), "bounds"));
  EXPECT_TRUE(contains(error_of("bounds: {min: [0, 0], max: [9, 9]}\nworld: {}\nrobot: {type: tank}\n"), "robot.type"));
  EXPECT_TRUE(contains(error_of("bounds: {min: [0, 0], max: [9, 9]}\nworld: {}\nrobot: {type: disc, radius: 1, shapes: []}\n"),
                       "robot.shapes"));
  EXPECT_TRUE(contains(error_of("bounds: {min: [0, 0], max: [9, 9]}\nworld: {}\n"
                                "robot: {type: arm, links: [{length: 1, width: 0.1}], limits: [[0, 1], [0, 1]]}\n"),
                       "robot.limits"));
  EXPECT_TRUE(contains(error_of(base + "world: {}\nresolution: 2\n"), "resolution"));
  EXPECT_EQ(error_of(base), "");  // no world: no obstacles
}

}  // namespace
}  // namespace amp::world
