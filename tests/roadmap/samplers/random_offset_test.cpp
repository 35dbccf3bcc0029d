// samplers/random_offset.cpp: the obstacle samplers' distance (sampler_distance), their shared
// settings check, and random_offset, a step of given length towards a uniform state.
#include "amp/roadmap/samplers/random_offset.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

const world::Problem& walls() {
  static const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/walls.yaml");
  return p;
}

TEST(SamplerDistance, RobotDiameterOrOnePercentOfTheExtent) {
  const world::Problem& p = walls();
  const SamplerDistance r = sampler_distance(*p.environment, *p.space, 2.0);
  EXPECT_FALSE(r.fallback);
  EXPECT_DOUBLE_EQ(r.d, 2.0 * p.environment->robot_min_diameter());
  const world::Problem point = test::point_problem(true);  // robot_min_diameter() = 0
  const SamplerDistance f = sampler_distance(*point.environment, *point.space, 1.0);
  EXPECT_TRUE(f.fallback);
  EXPECT_DOUBLE_EQ(f.d, 0.01 * std::sqrt(200.0));
}

// The step goes from `from` towards the uniform state u the same Rng draws, by delta, never past u:
// recomputed here from a copy of the Rng.
TEST(RandomOffset, StepsDeltaTowardsTheUniformDrawNeverPastIt) {
  const world::Problem p = test::point_problem(true);
  const State from = test::state2(2, 7);
  core::Rng rng(9);
  State out, u;
  for (int i = 0; i < 200; ++i) {
    const double delta = 0.05 * i;  // 0 to 9.95: some steps stop at u
    core::Rng copy = rng;
    p.space->sample_uniform(copy, u);
    random_offset(*p.space, rng, from, delta, out);
    const double to_u = p.space->distance(from, u);
    const State want = delta >= to_u ? u : State(from + (u - from) * (delta / to_u));
    EXPECT_NEAR((out - want).norm(), 0.0, 1e-12) << "delta " << delta;
    EXPECT_NEAR(p.space->distance(from, out), std::min(delta, to_u), 1e-12);
    EXPECT_TRUE(p.space->in_bounds(out));
  }
  random_offset(*p.space, rng, from, 0.0, out);
  EXPECT_EQ(out, from);
}

// On SE2 the step follows the space's geodesic, the angle the short way round, within the bounds.
TEST(RandomOffset, FollowsTheSpacesGeodesicOnSe2) {
  const core::JointSpace space = core::make_se2_space(0, 0, 4, 4, 1.0);
  const State from = (State(3) << 1, 1, 3.0).finished();
  core::Rng rng(4);
  State out, u, want;
  for (int i = 0; i < 100; ++i) {
    core::Rng copy = rng;
    space.sample_uniform(copy, u);
    random_offset(space, rng, from, 0.3, out);
    const double to_u = space.distance(from, u);
    space.interpolate(from, u, std::min(1.0, 0.3 / to_u), want);
    EXPECT_NEAR(space.distance(out, want), 0.0, 1e-12);
    EXPECT_NEAR(space.distance(from, out), std::min(0.3, to_u), 1e-9);
    EXPECT_TRUE(space.in_bounds(out));
  }
}

TEST(RandomOffset, SettingsCheckNamesTheSampler) {
  const auto message = [](double d, int attempts) {
    try {
      validate_offset_settings("expansion", d, attempts);
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(0.5, 1), "");
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    const std::string m = message(bad, 1);
    EXPECT_EQ(m.rfind("expansion sampler: d must be positive and finite", 0), 0u) << m;
  }
  EXPECT_EQ(message(0.5, 0).rfind("expansion sampler: max_attempts must be >= 1", 0), 0u) << message(0.5, 0);
}

}  // namespace
}  // namespace amp::roadmap
