#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "amp/core/error.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/polygon_geometry.hpp"
#include "support/state_of.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

using test::st;

TEST(PlanarRobot, ArmKinematicsPlaceEachJointAtTheEndOfThePreviousLink) {
  const PlanarRobot arm = PlanarRobot::fixed_arm({1, 2, kPi / 2}, {{2, 0.2}, {1, 0.2}, {0.5, 0.1}});
  EXPECT_EQ(arm.link_count(), 3);
  EXPECT_EQ(arm.state_dimension(), 3);
  Pose2 p[3];
  arm.link_poses(st({0, -kPi / 2, kPi / 2}), p);
  EXPECT_NEAR(p[0].x, 1, 1e-12);  // base, pointing up
  EXPECT_NEAR(p[0].y, 2, 1e-12);
  EXPECT_NEAR(p[1].x, 1, 1e-12);  // end of link 0: 2 up
  EXPECT_NEAR(p[1].y, 4, 1e-12);
  EXPECT_NEAR(p[1].theta, 0, 1e-12);
  EXPECT_NEAR(p[2].x, 2, 1e-12);  // end of link 1: 1 right
  EXPECT_NEAR(p[2].y, 4, 1e-12);
  const V tip = arm.reference_point(st({0, -kPi / 2, kPi / 2}));  // link 2 points up again, 0.5 long
  EXPECT_NEAR((tip - V(2, 4.5)).norm(), 0, 1e-12);
  // The link rectangle spans [-w/2, l + w/2] x [-w/2, w/2].
  EXPECT_NEAR(signed_area(arm.links()[0].polygons[0].vertices), 2.2 * 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(arm.min_diameter(), 0.1);
  EXPECT_NEAR(arm.radius(), 3 + std::hypot(0.55, 0.05), 1e-12);
}

TEST(PlanarRobot, FreeLinkageStartsWithThePoseOfLinkZero) {
  const PlanarRobot chain = PlanarRobot::free_linkage({{1, 0.2}, {1, 0.2}});
  EXPECT_EQ(chain.state_dimension(), 4);
  Pose2 p[2];
  chain.link_poses(st({3, 4, kPi, kPi / 2}), p);
  EXPECT_NEAR(p[1].x, 2, 1e-12);
  EXPECT_NEAR(p[1].y, 4, 1e-12);
  EXPECT_NEAR(p[1].theta, 1.5 * kPi, 1e-12);
  EXPECT_NEAR((chain.reference_point(st({3, 4, kPi, kPi / 2})) - V(2, 3)).norm(), 0, 1e-12);
}

TEST(PlanarRobot, RigidAndTranslatingMeasures) {
  const PlanarRobot rect = PlanarRobot::rigid({{Polygon{{{-2, -0.5}, {2, -0.5}, {2, 0.5}, {-2, 0.5}}}}, {}});
  EXPECT_EQ(rect.state_dimension(), 3);
  EXPECT_DOUBLE_EQ(rect.min_diameter(), 1.0);
  EXPECT_DOUBLE_EQ(rect.radius(), std::hypot(2.0, 0.5));
  const PlanarRobot disc = PlanarRobot::translating({{}, {Circle{{0, 0}, 0.7}}});
  EXPECT_EQ(disc.state_dimension(), 2);
  EXPECT_DOUBLE_EQ(disc.min_diameter(), 1.4);
  EXPECT_DOUBLE_EQ(disc.radius(), 0.7);
  EXPECT_EQ(PlanarRobot::translating({{}, {Circle{{0, 0}, 0.0}}}).min_diameter(), 0.0);
  EXPECT_THROW(PlanarRobot::rigid({}), ParameterError);
  EXPECT_THROW(PlanarRobot::rigid({{}, {Circle{{0, 0}, 0.0}}}), ParameterError);  // rigid: no points
  EXPECT_THROW(PlanarRobot::fixed_arm({}, {}), ParameterError);
  EXPECT_THROW(PlanarRobot::fixed_arm({}, {{1, 0}}), ParameterError);
  EXPECT_THROW(PlanarRobot::fixed_arm({}, {{1, 0.1}, {0.1, 0.2}, {1, 0.1}}), ParameterError);  // stubby middle
}

struct ArmFixture {
  explicit ArmFixture(PlanarRobot arm)
      : env(std::make_shared<const PlanarWorld>(Shapes2d{}, Eigen::AlignedBox2d(V(0, 0), V(10, 10))), std::move(arm)),
        checker(env.make_checker(counters)) {}
  core::Counters counters;
  PlanarEnvironment env;
  std::unique_ptr<ValidityChecker> checker;
};

// Independent self-collision reference: do links i and j (outlines) overlap?
bool links_overlap(const PlanarRobot& r, const State& s, int i, int j) {
  Pose2 p[kMaxDof];
  r.link_poses(s, p);
  return polygons_overlap(transform_shapes(r.links()[i], p[i]).polygons[0].vertices,
                          transform_shapes(r.links()[j], p[j]).polygons[0].vertices);
}

TEST(PlanarRobot, ArmSelfCollisionOnlyBetweenNonAdjacentLinks) {
  ArmFixture f(PlanarRobot::fixed_arm({5, 5, 0}, {{1, 0.2}, {1, 0.2}, {1, 0.2}}));
  EXPECT_TRUE(f.checker->is_valid(st({0, 0, 0})));  // straight: adjacent links overlap at joints only
  EXPECT_TRUE(f.checker->is_valid(st({0, kPi / 2, kPi / 2})));  // U turn: links 0 and 2 are 0.8 apart
  EXPECT_FALSE(links_overlap(f.env.robot(), st({0, kPi / 2, kPi / 2}), 0, 2));
  // Folding back 135 degrees twice sends link 2 down across link 0.
  const State folded = st({0, 0.75 * kPi, 0.75 * kPi});
  EXPECT_TRUE(links_overlap(f.env.robot(), folded, 0, 2));
  EXPECT_FALSE(f.checker->is_valid(folded));
  // Link 1 folded fully back over link 0 (adjacent, allowed) brings link 2 back past the base,
  // where its margin [3.9, 5.1] meets link 0's [4.9, 6.1].
  EXPECT_TRUE(links_overlap(f.env.robot(), st({0, kPi, 0}), 0, 2));
  EXPECT_FALSE(f.checker->is_valid(st({0, kPi, 0})));
  EXPECT_TRUE(f.checker->is_valid(st({kPi / 2, kPi / 2, -kPi / 2})));  // staircase: up, left, up
}

TEST(PlanarRobot, FourLinkArmFirstAndLastLinksCollide) {
  ArmFixture f(PlanarRobot::fixed_arm({5, 5, 0}, {{2, 0.2}, {1, 0.2}, {2, 0.2}, {1, 0.2}}));
  // Square loop: right 2, up 1, left 2, down 1 -> link 3 comes back down onto link 0's start.
  const State loop = st({0, kPi / 2, kPi / 2, kPi / 2});
  EXPECT_TRUE(links_overlap(f.env.robot(), loop, 0, 3));
  EXPECT_FALSE(links_overlap(f.env.robot(), loop, 0, 2));
  EXPECT_FALSE(f.checker->is_valid(loop));
  EXPECT_TRUE(f.checker->is_valid(st({0, kPi / 2, kPi / 2, 0})));  // last link continues left: free
}

TEST(PlanarEnvironment, DescribesWorldAndRobot) {
  const auto world = std::make_shared<const PlanarWorld>(
      Shapes2d{{Polygon{{{1, 1}, {2, 1}, {2, 2}}}}, {Circle{{5, 5}, 1}}}, Eigen::AlignedBox2d(V(0, 0), V(10, 8)));
  const PlanarEnvironment env(world, PlanarRobot::fixed_arm({5, 0, kPi / 2}, {{2, 0.2}, {1, 0.2}}));
  EXPECT_EQ(env.workspace_dimension(), 2);
  EXPECT_EQ(env.workspace_bounds().max(), Eigen::Vector3d(10, 8, 0));
  EXPECT_EQ(env.obstacle_outline().shapes.polygons.size(), 1u);
  EXPECT_EQ(env.obstacle_outline().grid, nullptr);
  const Shapes2d outline = env.robot_outline(st({0, 0}));
  ASSERT_EQ(outline.polygons.size(), 2u);
  EXPECT_NEAR(bounding_box(outline.polygons[1].vertices).max().y(), 3.1, 1e-12);
  EXPECT_NEAR((env.reference_point(st({0, 0})) - Eigen::Vector3d(5, 3, 0)).norm(), 0, 1e-12);
  EXPECT_DOUBLE_EQ(env.robot_min_diameter(), 0.2);
}

}  // namespace
}  // namespace amp::world
