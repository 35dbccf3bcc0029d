// samplers/gaussian_sampler.cpp: Gaussian sampling, the free one of a pair |N(0, d)| apart.
#include "amp/roadmap/samplers/gaussian_sampler.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(GaussianSampler, PairDistanceIsHalfNormalWithDeviationD) {
  // Point robot in the box world: the offsets themselves are measured through random_offset.
  const world::Problem p = test::point_problem(true);
  core::Rng rng(1);
  const State from = test::state2(5, 5);
  constexpr int kDraws = 20000;
  constexpr double kD = 0.3;
  double sq = 0.0;
  State out;
  for (int i = 0; i < kDraws; ++i) {
    random_offset(*p.space, rng, from, std::abs(rng.normal(0.0, kD)), out);
    sq += std::pow(p.space->distance(from, out), 2);
  }
  // E[|N(0, d)|^2] = d^2, except for the rare offsets cut short at the target (targets are >= ~0 away).
  EXPECT_NEAR(std::sqrt(sq / kDraws), kD, 0.02 * kD);
}

// The narrow-gap wall of the point world: a free sample's partner collided, so it lies inside a wall
// box, |N(0, d)| away: within 6 d of the wall (a 2e-9 chance per sample otherwise), on either side.
TEST(GaussianSampler, SamplesAreFreeAndWithinAFewDOfTheWall) {
  const world::Problem p = test::point_problem(true);
  const std::vector<test::Box> wall = {{4.5, 0.0, 5.5, 4.6}, {4.5, 5.4, 5.5, 10.0}};
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  constexpr double kD = 0.2;
  // About 2% of pairs straddle the wall's surface: enough attempts that no call gives up.
  GaussianSampler g(*p.space, *checker, GaussianSamplerSettings{kD, 5000});
  core::Rng rng(8);
  State q;
  int left = 0, right = 0;
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(g.sample(rng, q));
    const Eigen::Vector2d point(q[0], q[1]);
    for (const test::Box& b : wall) EXPECT_FALSE(b.contains(point)) << q.transpose();
    EXPECT_LE(std::min(wall[0].distance(point), wall[1].distance(point)), 6 * kD) << q.transpose();
    (q[0] < 5.0 ? left : right) += 1;
  }
  EXPECT_GT(left, 50);
  EXPECT_GT(right, 50);
  EXPECT_EQ(counters.cd_calls() % 2, 0u);  // two CD calls per pair
}

// With no obstacle every pair is free-free: the sampler gives up after max_attempts pairs, having
// spent exactly two CD calls on each.
TEST(GaussianSampler, WithoutObstaclesGivesUpAfterMaxAttemptsPairs) {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  GaussianSampler g(*p.space, *checker, GaussianSamplerSettings{0.5, 7});
  core::Rng rng(2);
  State q;
  EXPECT_FALSE(g.sample(rng, q));
  EXPECT_EQ(counters.cd_calls(), 14u);
}

TEST(GaussianSampler, SettingsErrorsNameTheSampler) {
  const auto message = [](GaussianSamplerSettings s) {
    try {
      s.validate();
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({-1.0, 10}).find("gaussian"), std::string::npos) << message({-1.0, 10});
  EXPECT_NE(message({1.0, 0}).find("max_attempts"), std::string::npos) << message({1.0, 0});
  EXPECT_EQ(message({std::nextafter(0.0, 1.0), 1}), "");
}

}  // namespace
}  // namespace amp::roadmap
