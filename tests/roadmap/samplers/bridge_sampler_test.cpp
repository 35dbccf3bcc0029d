// samplers/bridge_sampler.cpp: the bridge test, free midpoints of short colliding pairs.
#include "amp/roadmap/samplers/bridge_sampler.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

// The point world's wall x in [4.5, 5.5] with its gap y in (4.6, 5.4): both ends of a bridge lie in
// the wall (nothing else collides), so a free midpoint has x in [4.5, 5.5] and can only be in the gap.
TEST(BridgeSampler, EverySampleLiesInTheNarrowGap) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  BridgeSamplerSettings b;
  b.d = 0.5;
  b.max_attempts = 100000;
  BridgeSampler bridge(*p.space, *checker, b);
  core::Rng rng(6);
  State q;
  for (int i = 0; i < 30; ++i) {
    ASSERT_TRUE(bridge.sample(rng, q));
    EXPECT_GE(q[0], 4.5);
    EXPECT_LE(q[0], 5.5);
    EXPECT_GT(q[1], 4.6);
    EXPECT_LT(q[1], 5.4);
  }
}

// A free first end ends the attempt at one CD call: with no obstacle, max_attempts CD calls.
TEST(BridgeSampler, WithoutObstaclesGivesUpAfterMaxAttemptsAtOneCdCallEach) {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  BridgeSamplerSettings b;
  b.max_attempts = 12;
  BridgeSampler bridge(*p.space, *checker, b);
  core::Rng rng(1);
  State q;
  EXPECT_FALSE(bridge.sample(rng, q));
  EXPECT_EQ(counters.cd_calls(), 12u);
}

// uniform_mix = 1: every call is a plain uniform free sample, so it succeeds where no bridge exists.
TEST(BridgeSampler, UniformMixOfOneSamplesUniformly) {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  BridgeSamplerSettings b;
  b.uniform_mix = 1.0;
  BridgeSampler bridge(*p.space, *checker, b);
  core::Rng rng(1);
  State q;
  double mean_x = 0.0;
  for (int i = 0; i < 2000; ++i) {
    ASSERT_TRUE(bridge.sample(rng, q));
    EXPECT_TRUE(p.space->in_bounds(q));
    mean_x += q[0] / 2000;
  }
  EXPECT_NEAR(mean_x, 5.0, 0.3);  // sd of the mean: 10 / sqrt(12 x 2000) = 0.065
  b.uniform_mix = -0.1;
  EXPECT_THROW(b.validate(), ParameterError);
  b.uniform_mix = 0.0;
  b.d = 0.0;
  EXPECT_THROW(b.validate(), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
