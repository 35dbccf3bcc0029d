#include "amp/roadmap/local_planners/edge_certifier.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/polygon_geometry.hpp"
#include "amp/world/problem.hpp"

namespace amp::roadmap {
namespace {

constexpr double kRobotRadius = 0.05;
constexpr double kSliverWidth = 1e-4;  // far below the space's resolution: discrete checks step over it

world::Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

// A disc robot in [0, 10]^2; a sliver wall at x = 5 from y = 0 to y = 8 (the way round is above it).
world::Problem sliver_problem(core::EdgeCheckMode mode) {
  world::Shapes2d obstacles;
  obstacles.polygons.push_back(rectangle(5.0, 0.0, 5.0 + kSliverWidth, 8.0));
  auto world = std::make_shared<const world::PlanarWorld>(
      std::move(obstacles), Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10)));
  world::Shapes2d body;
  body.circles.push_back({Eigen::Vector2d::Zero(), kRobotRadius});
  world::Problem p;
  p.name = "sliver";
  p.environment = std::make_shared<world::PlanarEnvironment>(world, world::PlanarRobot::translating(std::move(body)));
  // Its resolution, 0.01 of the diagonal (0.14), is far above the sliver's width.
  p.space = std::make_shared<core::JointSpace>(core::make_rn_space({0.0, 0.0}, {10.0, 10.0}));
  State start(2), goal(2);
  start << 1.0, 2.0;
  goal << 9.0, 2.0;
  p.seeds = {start, goal};
  p.defaults.edge_check = mode;
  return p;
}

// Independent of every checker: a path segment crosses the sliver when the disc swept along it
// comes within its radius of the sliver's rectangle.
bool crosses_sliver(const State& a, const State& b) {
  const world::Polygon s = rectangle(5.0, 0.0, 5.0 + kSliverWidth, 8.0);
  const Eigen::Vector2d p(a[0], a[1]), q(b[0], b[1]);
  for (std::size_t i = 0, j = 3; i < 4; j = i++) {
    if (world::segment_segment_distance_sq(p, q, s.vertices[j], s.vertices[i]) <= kRobotRadius * kRobotRadius) {
      return true;
    }
  }
  return false;
}

TEST(EdgeCertifier, RefusesTheSliverThatDiscreteChecksStepOver) {
  const world::Problem p = sliver_problem(core::EdgeCheckMode::kDiscrete);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  ASSERT_GT(p.space->resolution(), 10 * kSliverWidth);
  StraightLinePlanner discrete(*p.space, *checker);
  EXPECT_TRUE(discrete.connect(p.seeds[0], p.seeds[1])) << "the sliver should fall between check points";
  EdgeCertifier certifier(*p.space, *checker);
  const std::uint64_t cd_before = counters.cd_calls();
  EXPECT_FALSE(certifier.certify(p.seeds[0], p.seeds[1]));
  EXPECT_EQ(counters.cd_calls(), cd_before) << "certification costs clearance calls, not CD calls";
  EXPECT_GT(counters.clearance_calls(), 0u);
  EXPECT_EQ(certifier.segments_refused(), 1u);
  // Above the sliver the same kind of segment is proven free.
  State a(2), b(2);
  a << 1.0, 9.0;
  b << 9.0, 9.0;
  EXPECT_TRUE(certifier.certify(a, b));
  EXPECT_EQ(certifier.segments_certified(), 1u);
}

TEST(EdgeCertifier, NoPlannedPathCrossesTheSliver) {
  for (const auto mode : {core::EdgeCheckMode::kDiscrete, core::EdgeCheckMode::kCertified}) {
    const world::Problem p = sliver_problem(mode);
    for (const bool lazy : {false, true}) {
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        core::Counters counters;
        const auto checker = p.environment->make_checker(counters);
        const core::StopCondition stop(1e6, 3000);
        const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds, mode, &stop};
        core::Rng rng(seed);
        PrmSettings settings;
        settings.lazy = lazy;
        settings.smooth = true;
        const PlanResult r = Prm(settings).plan(ctx, stop, rng);
        ASSERT_EQ(r.status, core::PlanStatus::kSolved) << "seed " << seed;
        for (std::size_t i = 1; i < r.path.size(); ++i) {
          EXPECT_FALSE(crosses_sliver(r.path[i - 1], r.path[i])) << "seed " << seed << " segment " << i;
        }
        EXPECT_EQ(r.path.front(), p.seeds.front());
        EXPECT_EQ(r.path.back(), p.seeds.back());
      }
    }
  }
}

// The motion bound must hold: no robot point travels farther than it along the interpolation.
TEST(EdgeCertifier, MotionBoundCoversTheRigidBodysPoints) {
  world::Shapes2d obstacles;
  auto world = std::make_shared<const world::PlanarWorld>(
      std::move(obstacles), Eigen::AlignedBox2d(Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, 10)));
  world::Shapes2d body;
  body.polygons.push_back(rectangle(-1.0, -0.2, 2.0, 0.2));
  const world::PlanarEnvironment env(world, world::PlanarRobot::rigid(body));
  const core::JointSpace space = core::make_se2_space(-10, -10, 10, 10, 2.0);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  core::Rng rng(7);
  State a, b, s, prev;
  for (int trial = 0; trial < 200; ++trial) {
    space.sample_uniform(rng, a);
    space.sample_uniform(rng, b);
    const double bound = checker->motion_bound(a, b);
    // The corner (2, 0.2) is the farthest point; follow it finely and sum its travel.
    double travel = 0.0;
    const auto corner = [](const State& q) {
      return Eigen::Vector2d(q[0] + 2.0 * std::cos(q[2]) - 0.2 * std::sin(q[2]),
                             q[1] + 2.0 * std::sin(q[2]) + 0.2 * std::cos(q[2]));
    };
    space.interpolate(a, b, 0.0, prev);
    for (int i = 1; i <= 1000; ++i) {
      space.interpolate(a, b, i / 1000.0, s);
      travel += (corner(s) - corner(prev)).norm();
      prev = s;
    }
    EXPECT_LE(travel, bound * (1 + 1e-9)) << trial;
  }
}

}  // namespace
}  // namespace amp::roadmap
