#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "amp/core/se3_space.hpp"
#include "amp/world/spatial_environment.hpp"

namespace amp::world {
namespace {

using Eigen::Vector3d;

const Eigen::AlignedBox3d kBounds(Vector3d(-10, -10, -10), Vector3d(10, 10, 10));

std::shared_ptr<const SpatialWorld> cube_world() {  // the cube [-1, 1]^3
  return std::make_shared<const SpatialWorld>(std::vector<Solid>{Solid::box({2, 2, 2})}, kBounds);
}

State se3(double x, double y, double z, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  return core::Se3Space::make_state({x, y, z}, q);
}

State xyz(double x, double y, double z) {
  State s(3);
  s << x, y, z;
  return s;
}

TEST(SpatialChecker, BoxAgainstBoxTouchingAndApart) {
  core::Counters counters;
  const SpatialEnvironment env(cube_world(), SpatialRobot::rigid({Solid::box({1, 1, 1})}));
  auto checker = env.make_checker(counters);
  EXPECT_FALSE(checker->is_valid(se3(1.49, 0, 0)));  // faces overlap by 0.01
  EXPECT_TRUE(checker->is_valid(se3(1.51, 0, 0)));
  EXPECT_FALSE(checker->is_valid(se3(0, 0, 0)));  // inside
  EXPECT_TRUE(checker->is_valid(se3(1.4, 1.6, 0)));  // diagonal, clear on y
  EXPECT_EQ(counters.cd_calls(), 4u);
}

TEST(SpatialChecker, RotatedBoxReachesFurther) {
  // A unit cube turned 45 degrees about z reaches sqrt(2)/2 from its centre along x.
  core::Counters counters;
  const SpatialEnvironment env(cube_world(), SpatialRobot::rigid({Solid::box({1, 1, 1})}));
  auto checker = env.make_checker(counters);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitZ()));
  const double reach = 1.0 + std::sqrt(0.5);
  EXPECT_FALSE(checker->is_valid(se3(reach - 0.01, 0, 0, q)));
  EXPECT_TRUE(checker->is_valid(se3(reach + 0.01, 0, 0, q)));
  EXPECT_FALSE(checker->is_valid(se3(1.51, 0, 0, q)));  // free unrotated, not rotated
}

TEST(SpatialChecker, RotatedObstacle) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.rotate(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitZ()));
  auto world = std::make_shared<const SpatialWorld>(std::vector<Solid>{Solid::box({2, 2, 2}, pose)}, kBounds);
  core::Counters counters;
  const SpatialEnvironment env(world, SpatialRobot::sphere(0.5));
  auto checker = env.make_checker(counters);
  const double corner = std::sqrt(2.0);  // the obstacle's corner on the x axis
  EXPECT_FALSE(checker->is_valid(xyz(corner + 0.49, 0, 0)));
  EXPECT_TRUE(checker->is_valid(xyz(corner + 0.51, 0, 0)));
}

TEST(SpatialChecker, SphereInsideBoxAndCylinder) {
  Eigen::Isometry3d lying = Eigen::Isometry3d(Eigen::Translation3d(5, 0, 0));
  lying.rotate(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()));  // axis along x
  auto world = std::make_shared<const SpatialWorld>(
      std::vector<Solid>{Solid::box({2, 2, 2}), Solid::cylinder(1.0, 4.0, lying)}, kBounds);
  core::Counters counters;
  const SpatialEnvironment env(world, SpatialRobot::sphere(0.25));
  auto checker = env.make_checker(counters);
  EXPECT_FALSE(checker->is_valid(xyz(0.2, 0.3, -0.1)));   // inside the box
  EXPECT_FALSE(checker->is_valid(xyz(6.5, 0, 0)));        // inside the cylinder, off its centre
  EXPECT_TRUE(checker->is_valid(xyz(7.3, 0, 0)));         // past its end (x = 7) by 0.3
  EXPECT_FALSE(checker->is_valid(xyz(5, 0, 1.2)));        // 0.2 above its side
  EXPECT_TRUE(checker->is_valid(xyz(5, 0, 1.3)));
}

TEST(SpatialChecker, BoundsUseTheWholeRobotOrOnlyItsReferencePoint) {
  core::Counters counters;
  const SpatialEnvironment strict(cube_world(), SpatialRobot::sphere(0.5));
  const SpatialEnvironment ompl(cube_world(), SpatialRobot::sphere(0.5), SpatialBoundsCheck::kReferencePoint);
  auto a = strict.make_checker(counters);
  auto b = ompl.make_checker(counters);
  EXPECT_FALSE(a->is_valid(xyz(9.6, 0, 0)));
  EXPECT_TRUE(a->is_valid(xyz(9.4, 0, 0)));
  EXPECT_TRUE(b->is_valid(xyz(9.6, 0, 0)));
  EXPECT_FALSE(b->is_valid(xyz(10.1, 0, 0)));
  // A rotated box: its exact world box is checked, not FCL's loose bounding cube.
  const SpatialEnvironment rod(cube_world(), SpatialRobot::rigid({Solid::box({4, 0.2, 0.2})}));
  auto c = rod.make_checker(counters);
  EXPECT_TRUE(c->is_valid(se3(5, 9.85, 0)));  // lying along x, 0.05 from the y wall
  const Eigen::Quaterniond up(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()));
  EXPECT_FALSE(c->is_valid(se3(5, 0, 8.5, up)));  // standing: top at 10.5
  EXPECT_TRUE(c->is_valid(se3(5, 0, 7.5, up)));
}

TEST(SpatialChecker, ClearanceMatchesHandComputedNearestPoints) {
  core::Counters counters;
  const SpatialEnvironment env(cube_world(), SpatialRobot::sphere(0.5));
  auto checker = env.make_checker(counters);
  const Clearance c = checker->clearance(xyz(3, 0, 0));
  EXPECT_NEAR(c.distance, 1.5, 1e-6);
  EXPECT_TRUE(c.robot_point.isApprox(Vector3d(2.5, 0, 0), 1e-4)) << c.robot_point.transpose();
  EXPECT_TRUE(c.obstacle_point.isApprox(Vector3d(1, 0, 0), 1e-4)) << c.obstacle_point.transpose();
  // Off a corner: distance from (3, 3, 3) to (1, 1, 1) minus the radius.
  EXPECT_NEAR(checker->clearance(xyz(3, 3, 3)).distance, 2 * std::sqrt(3.0) - 0.5, 1e-6);
  EXPECT_EQ(checker->clearance(xyz(0.5, 0, 0)).distance, 0.0);  // in collision
  EXPECT_EQ(counters.clearance_calls(), 3u);
  EXPECT_EQ(counters.cd_calls(), 0u);
}

TEST(SpatialChecker, ClearanceOfAMeshRobotToTheNearestOfSeveralObstacles) {
  auto world = std::make_shared<const SpatialWorld>(
      std::vector<Solid>{Solid::box({2, 2, 2}), Solid::sphere(1.0, {0, 6, 0})}, kBounds);
  TriangleMesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  core::Counters counters;
  const SpatialEnvironment env(world, SpatialRobot::rigid({Solid::mesh_of(tetra)}));
  auto checker = env.make_checker(counters);
  // Tetra at (0, 3, 0): its apex (0, 4, 0) is 1 from the sphere's surface, its base 2 from the box.
  const Clearance c = checker->clearance(se3(0, 3, 0));
  EXPECT_NEAR(c.distance, 1.0, 1e-6);
  EXPECT_TRUE(c.robot_point.isApprox(Vector3d(0, 4, 0), 1e-4)) << c.robot_point.transpose();
  EXPECT_TRUE(c.obstacle_point.isApprox(Vector3d(0, 5, 0), 1e-4)) << c.obstacle_point.transpose();
  EXPECT_TRUE(checker->is_valid(se3(0, 3, 0)));
  EXPECT_FALSE(checker->is_valid(se3(0, 4.5, 0)));
  // Turned 90 degrees about z the apex points to -x: nearest are now the box's face and the base.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitZ()));
  const Clearance turned = checker->clearance(se3(0.5, 2.5, 0, q));
  EXPECT_NEAR(turned.distance, 1.5, 1e-6);
  EXPECT_NEAR(turned.robot_point.y(), 2.5, 1e-6);
  EXPECT_NEAR(turned.obstacle_point.y(), 1.0, 1e-6);
}

TEST(SpatialChecker, ClearanceOfASphereRobotToAMeshObstacle) {
  TriangleMesh tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  Eigen::Isometry3d pose(Eigen::Translation3d(0, 3, 0));
  pose.rotate(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitZ()));  // apex at (-1, 3, 0)
  auto world = std::make_shared<const SpatialWorld>(std::vector<Solid>{Solid::mesh_of(tetra, pose)}, kBounds);
  core::Counters counters;
  for (const SpatialRobot& robot : {SpatialRobot::sphere(1.0), SpatialRobot::rigid({Solid::sphere(1.0, Vector3d::Zero())})}) {
    auto checker = SpatialEnvironment(world, robot).make_checker(counters);
    const State s = robot.kind() == SpatialRobot::Kind::kSphere ? xyz(-5, 0, 0) : se3(-5, 0, 0);
    const Clearance c = checker->clearance(s);
    EXPECT_NEAR(c.distance, 4.0, 1e-6);  // |(-1, 3) - (-5, 0)| - 1
    EXPECT_TRUE(c.obstacle_point.isApprox(Vector3d(-1, 3, 0), 1e-4)) << c.obstacle_point.transpose();
    EXPECT_TRUE(c.robot_point.isApprox(Vector3d(-4.2, 0.6, 0), 1e-4)) << c.robot_point.transpose();
  }
}

TEST(SpatialChecker, EmptyWorldHasInfiniteClearance) {
  auto world = std::make_shared<const SpatialWorld>(std::vector<Solid>{}, kBounds);
  core::Counters counters;
  auto checker = SpatialEnvironment(world, SpatialRobot::sphere(1)).make_checker(counters);
  EXPECT_TRUE(checker->is_valid(xyz(0, 0, 0)));
  EXPECT_TRUE(std::isinf(checker->clearance(xyz(0, 0, 0)).distance));
}

TEST(SpatialEnvironment, TopViewOutlines) {
  auto world = std::make_shared<const SpatialWorld>(
      std::vector<Solid>{Solid::box({2, 4, 1}), Solid::sphere(1.0, {5, 5, 5})}, kBounds);
  const SpatialEnvironment env(world, SpatialRobot::rigid({Solid::box({1, 1, 1})}));
  const Outline o = env.obstacle_outline();
  ASSERT_EQ(o.shapes.polygons.size(), 1u);
  ASSERT_EQ(o.shapes.polygons[0].vertices.size(), 4u);
  Eigen::AlignedBox2d box;
  for (const auto& v : o.shapes.polygons[0].vertices) box.extend(v);
  EXPECT_TRUE(box.min().isApprox(Eigen::Vector2d(-1, -2)));
  EXPECT_TRUE(box.max().isApprox(Eigen::Vector2d(1, 2)));
  ASSERT_EQ(o.shapes.circles.size(), 1u);
  EXPECT_DOUBLE_EQ(o.shapes.circles[0].radius, 1.0);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitZ()));
  const Shapes2d robot = env.robot_outline(se3(3, 0, 0, q));
  ASSERT_EQ(robot.polygons.size(), 1u);
  ASSERT_EQ(robot.polygons[0].vertices.size(), 4u);
  for (const auto& v : robot.polygons[0].vertices) EXPECT_NEAR((v - Eigen::Vector2d(3, 0)).norm(), std::sqrt(0.5), 1e-9);
  EXPECT_TRUE(env.reference_point(se3(3, 2, 1)).isApprox(Vector3d(3, 2, 1)));
  EXPECT_NEAR(env.robot_radius(), std::sqrt(0.75), 1e-12);
  EXPECT_DOUBLE_EQ(env.robot_min_diameter(), 1.0);
}

}  // namespace
}  // namespace amp::world
