#include "amp/world/spatial_robot.hpp"

#include <gtest/gtest.h>

#include <array>
#include <numbers>

#include "amp/core/error.hpp"
#include "amp/world/spatial_environment.hpp"

namespace amp::world {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

ScaraParams arm() {
  ScaraParams p;
  p.base = {1, 2, 0};
  p.column_height = 1.0;
  p.upper_arm = 0.5;
  p.forearm = 0.4;
  p.link_radius = 0.05;
  p.wrist_length = 0.1;
  p.slide_lo = 0.2;
  p.slide_hi = 0.9;
  p.limits = {{{-kPi, kPi}, {-kPi, kPi}, {-3.1, 3.1}, {-kPi, kPi}}};
  p.tool = {Solid::box({0.04, 0.04, 0.2}, Eigen::Isometry3d(Eigen::Translation3d(0, 0, -0.1)))};
  p.tip = {0, 0, -0.2};
  return p;
}

State q(double yaw, double z, double t1, double t2, double wrist) {
  State s(5);
  s << yaw, z, t1, t2, wrist;
  return s;
}

TEST(SpatialRobot, ScaraForwardKinematicsByHand) {
  const SpatialRobot robot = SpatialRobot::scara(arm());
  std::array<Eigen::Isometry3d, SpatialRobot::kMaxLinks> poses;
  // yaw 90 deg, arm at 0.6, elbow 90 deg, wrist 90 deg.
  robot.link_poses(q(kPi / 2, 0.6, 0, kPi / 2, kPi / 2), poses.data());
  // Shoulder (1, 2, 0.6); upper arm along +y to the elbow (1, 2.5, 0.6); forearm along -x to
  // the wrist (0.6, 2.5, 0.6); flange 0.1 lower; tool yaw 270 deg.
  EXPECT_TRUE(poses[0].translation().isApprox(Vector3d(1, 2, 0)));
  EXPECT_TRUE(poses[1].translation().isApprox(Vector3d(1, 2, 0.6)));
  EXPECT_TRUE((poses[1] * Vector3d(0.5, 0, 0)).isApprox(Vector3d(1, 2.5, 0.6)));
  EXPECT_TRUE(poses[2].translation().isApprox(Vector3d(1, 2.5, 0.6)));
  EXPECT_TRUE(poses[3].translation().isApprox(Vector3d(0.6, 2.5, 0.6)));
  EXPECT_TRUE(poses[4].translation().isApprox(Vector3d(0.6, 2.5, 0.5)));
  EXPECT_TRUE((poses[4].linear() * Vector3d::UnitX()).isApprox(Vector3d(0, -1, 0), 1e-12));
  EXPECT_TRUE(robot.reference_point(q(kPi / 2, 0.6, 0, kPi / 2, kPi / 2)).isApprox(Vector3d(0.6, 2.5, 0.3)));
  // Stretched out along x at the lowest slide position.
  EXPECT_TRUE(robot.reference_point(q(0, 0.2, 0, 0, 0)).isApprox(Vector3d(1.9, 2, -0.1)));
  EXPECT_NEAR(robot.radius(), 0.5 + 0.4 + 0.05, 1e-12);
  EXPECT_EQ(robot.self_pairs().size(), 6u);
}

TEST(SpatialRobot, ScaraSelfCollisionOnlyBetweenNonAdjacentLinks) {
  ScaraParams p = arm();
  p.forearm = 0.5;  // folded back, the wrist comes back onto the column
  auto world = std::make_shared<const SpatialWorld>(
      std::vector<Solid>{}, Eigen::AlignedBox3d(Vector3d(-5, -5, -5), Vector3d(5, 5, 5)));
  core::Counters counters;
  const SpatialEnvironment env(world, SpatialRobot::scara(p));
  auto checker = env.make_checker(counters);
  EXPECT_TRUE(checker->is_valid(q(0, 0.6, 0, 0, 0)));     // upper arm overlaps the column: adjacent
  EXPECT_TRUE(checker->is_valid(q(0, 0.6, 0, 1.5, 0)));
  EXPECT_FALSE(checker->is_valid(q(0, 0.6, 0, 3.05, 0)));  // forearm and wrist over the column
  // A partial fold keeps the wrist 0.31 from the column's axis.
  EXPECT_TRUE(checker->is_valid(q(0, 0.6, 0, 2.5, 0)));
}

TEST(SpatialRobot, ScaraAgainstAnObstacle) {
  auto world = std::make_shared<const SpatialWorld>(
      std::vector<Solid>{Solid::box({0.2, 0.2, 0.2}, Eigen::Isometry3d(Eigen::Translation3d(1.9, 2, 0.1)))},
      Eigen::AlignedBox3d(Vector3d(-5, -5, -5), Vector3d(5, 5, 5)));
  core::Counters counters;
  const SpatialEnvironment env(world, SpatialRobot::scara(arm()));
  auto checker = env.make_checker(counters);
  EXPECT_FALSE(checker->is_valid(q(0, 0.35, 0, 0, 0)));  // tool tip at z 0.05 inside the block
  EXPECT_TRUE(checker->is_valid(q(0, 0.6, 0, 0, 0)));    // tool tip at 0.3, block top at 0.2
  EXPECT_TRUE(checker->is_valid(q(kPi / 2, 0.35, 0, 0, 0)));
  EXPECT_NEAR(checker->clearance(q(0, 0.6, 0, 0, 0)).distance, 0.1, 1e-6);
}

TEST(SpatialRobot, RigidPoseFromQuaternion) {
  const SpatialRobot robot = SpatialRobot::rigid({Solid::box({2, 1, 1})});
  State s(7);
  const Eigen::Quaterniond r(Eigen::AngleAxisd(kPi / 2, Vector3d::UnitZ()));
  s << 1, 2, 3, r.x(), r.y(), r.z(), r.w();
  Eigen::Isometry3d pose;
  robot.link_poses(s, &pose);
  EXPECT_TRUE((pose * Vector3d(1, 0, 0)).isApprox(Vector3d(1, 3, 3)));
  EXPECT_DOUBLE_EQ(robot.min_diameter(), 1.0);
}

TEST(SpatialRobot, RejectsBadScaraParameters) {
  ScaraParams p = arm();
  p.slide_hi = 1.5;  // leaves the column
  EXPECT_THROW(SpatialRobot::scara(p), ParameterError);
  p = arm();
  p.tool.clear();
  EXPECT_THROW(SpatialRobot::scara(p), ParameterError);
  EXPECT_THROW(SpatialRobot::rigid({}), ParameterError);
}

}  // namespace
}  // namespace amp::world
