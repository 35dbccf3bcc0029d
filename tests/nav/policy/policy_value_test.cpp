#include "amp/nav/policy/policy_value.hpp"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/unicycle_space.hpp"
#include "amp/nav/polygon_nav_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

State w(double x, double y, double v) { return core::UnicycleSpace::make_state(x, y, 0.0, v, 0.0); }

// A 10 x 4 m room with a thin wall along y = 2 from x = 6 to 10.
std::shared_ptr<const PolygonNavWorld> room() {
  world::Shapes2d s;
  s.segments.push_back({{6.0, 2.0}, {10.0, 2.0}});
  return std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), V(10, 4)));
}

TEST(PolicyValue, FarFromObstaclesItIsDistanceAndTimeByHand) {
  const auto world = room();
  const PolicyValue value(*world, 0.2);  // c 1, c_time 1, g 100
  // 2 m at 0.2 m/s in open space: -(1 + 1 / 0.2) * 2 = -12; the whole policy adds g.
  const std::vector<State> p{w(1, 1, 0.2), w(3, 1, 0.2)};
  EXPECT_NEAR(value.segments(p, 0, 1), -12.0, 1e-9);
  EXPECT_NEAR(value.total(p), 88.0, 1e-9);
  // Speed from 0.1 to 0.3 along 1 m: the midpoint rule on 50 pieces of 2 cm (speed at each
  // piece's middle), computed here independently.
  const std::vector<State> q{w(1, 1, 0.1), w(2, 1, 0.3)};
  double expected = 0.0;
  for (int i = 0; i < 50; ++i) expected += -(1.0 + 1.0 / (0.1 + 0.2 * (i + 0.5) / 50)) * 0.02;
  EXPECT_NEAR(value.segments(q, 0, 1), expected, 1e-9);
}

TEST(PolicyValue, InsideTheSafetyRangeCostsHByItsSigmaPointWeights) {
  const auto world = room();
  PolicyRewardSettings s;
  s.safety = 0.1;
  s.safety_per_speed = 0.0;
  s.sigma = 0.1;  // sigma points at +-0.1732 m
  const PolicyValue value(*world, 0.2, s);
  // Along the wall 0.35 m below it: clearance 0.15 > 0.1 on the path, but the point 0.17 m nearer has
  // clearance -0.02: weight 1/6 of h, over 2 m: -(1 + 5 + 50 / 6) * 2.
  const std::vector<State> near{w(7, 1.65, 0.2), w(9, 1.65, 0.2)};
  EXPECT_NEAR(value.segments(near, 0, 1), -(6.0 + 50.0 / 6.0) * 2.0, 1e-9);
  // 0.25 m below: the path (clearance 0.05) and the nearer point: 5/6 of h.
  const std::vector<State> nearer{w(7, 1.75, 0.2), w(9, 1.75, 0.2)};
  EXPECT_NEAR(value.segments(nearer, 0, 1), -(6.0 + 50.0 * 5.0 / 6.0) * 2.0, 1e-9);
  // The lowest immediate reward on a segment that ends beside the wall is beside it.
  const std::vector<State> into{w(4, 1.75, 0.2), w(9, 1.75, 0.2)};
  const PolicyValue::Lowest low = value.lowest_on_segment(into, 0);
  EXPECT_NEAR(low.reward, -(6.0 + 50.0 * 5.0 / 6.0), 1e-9);
  EXPECT_GT(low.point.x(), 5.8);
}

TEST(PolicyValue, RefusesBadSettings) {
  const auto world = room();
  PolicyRewardSettings s;
  s.sigma = -1.0;
  EXPECT_THROW(PolicyValue(*world, 0.2, s), ParameterError);
  EXPECT_THROW(PolicyValue(*world, 0.0), ParameterError);
}

}  // namespace
}  // namespace amp::nav
