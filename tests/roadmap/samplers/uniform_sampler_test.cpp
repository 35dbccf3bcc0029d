#include "amp/roadmap/samplers/uniform_sampler.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(UniformSampler, ReturnsFreeStatesAndCountsEveryDraw) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  // Left half blocked: about half the draws are rejected.
  test::BoxEnvironment env({{0.0, 0.0, 5.0, 10.0}}, test::RobotKind::kPoint);
  std::vector<State> record;
  env.set_record(&record);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  UniformSampler sampler(space, *checker);
  core::Rng rng(5);
  State s;
  for (int i = 0; i < 200; ++i) {
    ASSERT_TRUE(sampler.sample(rng, s));
    EXPECT_GT(s[0], 5.0);
    EXPECT_TRUE(space.in_bounds(s));
    EXPECT_EQ(record.back(), s);  // the returned state is the last one checked
  }
  EXPECT_EQ(counters.cd_calls(), record.size());
  EXPECT_GT(record.size(), 300u);  // rejections were counted too
  EXPECT_LT(record.size(), 500u);
}

TEST(UniformSampler, GivesUpAfterMaxAttempts) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  test::BoxEnvironment env({{-1.0, -1.0, 11.0, 11.0}}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  UniformSampler sampler(space, *checker, {.max_attempts = 7});
  core::Rng rng(5);
  State s;
  EXPECT_FALSE(sampler.sample(rng, s));
  EXPECT_EQ(counters.cd_calls(), 7u);
  EXPECT_THROW(UniformSampler(space, *checker, {.max_attempts = 0}), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
