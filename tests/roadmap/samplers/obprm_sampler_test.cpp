// samplers/obprm_sampler.cpp: obstacle-based sampling, the first free state along a ray out of an
// obstacle, at the space's resolution.
#include "amp/roadmap/samplers/obprm_sampler.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

// One box in the middle of the point world: every colliding seed is inside it, and the walk's
// previous state collided, so each sample lies outside the box within one resolution step of it.
TEST(ObprmSampler, SamplesAreFreeWithinOneResolutionStepOfTheObstacle) {
  world::Problem p = test::point_problem(true);
  const std::vector<test::Box> boxes = {{3, 3, 7, 7}};
  p.environment = std::make_shared<test::BoxEnvironment>(boxes, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  ObprmSampler o(*p.space, *checker);
  core::Rng rng(4);
  const double step = p.space->resolution();
  State q;
  int sides[4] = {0, 0, 0, 0};  // left, right, below, above the box
  for (int i = 0; i < 200; ++i) {
    ASSERT_TRUE(o.sample(rng, q));
    const Eigen::Vector2d point(q[0], q[1]);
    EXPECT_FALSE(boxes[0].contains(point)) << q.transpose();
    EXPECT_LE(boxes[0].distance(point), step + 1e-12) << q.transpose();
    ++sides[q[0] < 3 ? 0 : q[0] > 7 ? 1 : q[1] < 3 ? 2 : 3];
  }
  for (int s = 0; s < 4; ++s) EXPECT_GT(sides[s], 20) << "side " << s;  // the rays leave every way
}

// Free seeds are skipped at one CD call each: with no obstacle, max_attempts draws and no sample.
TEST(ObprmSampler, WithoutObstaclesGivesUpAfterMaxAttemptsDraws) {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  ObprmSampler o(*p.space, *checker, ObprmSamplerSettings{9, 1000});
  core::Rng rng(3);
  State q;
  EXPECT_FALSE(o.sample(rng, q));
  EXPECT_EQ(counters.cd_calls(), 9u);
}

// A ray of max_steps = 1 reaches one resolution step only: out of the big box, no seed deeper than
// one step inside finds a free state, so every sample is within 1 step and far fewer succeed.
TEST(ObprmSampler, MaxStepsBoundsTheWalk) {
  world::Problem p = test::point_problem(true);
  const std::vector<test::Box> boxes = {{1, 1, 9, 9}};
  p.environment = std::make_shared<test::BoxEnvironment>(boxes, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  ObprmSampler o(*p.space, *checker, ObprmSamplerSettings{1, 1});
  core::Rng rng(5);
  State q;
  int found = 0;
  for (int i = 0; i < 400; ++i) {
    if (!o.sample(rng, q)) continue;
    ++found;
    EXPECT_LE(boxes[0].distance(Eigen::Vector2d(q[0], q[1])), p.space->resolution() + 1e-12);
  }
  // Only a seed within one step (1% of the extent, 0.14) of the box's border can succeed: a band
  // of area 32 x 0.14 = 4.5% of the space, and then only for a ray pointing out of the box.
  EXPECT_LT(found, 40);
  EXPECT_THROW(ObprmSamplerSettings({0, 10}).validate(), ParameterError);
}

// A box over the whole world: every ray walks in vain until it reaches its end (thousands of CD
// calls per sample() here, up to max_attempts x max_steps).
// With a run's stop condition past its deadline the sampler gives up at the first poll (one
// StopPoll stride of CD calls), and once stopped it makes no CD call at all. (A run at a fine
// resolution overshot its time limit by 80 ms in one sample() before the poll.)
TEST(ObprmSampler, AStoppedRunEndsTheWalkWithinOnePollStride) {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{{-1, -1, 11, 11}}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const core::StopCondition expired(0.0, 1000);
  ObprmSampler o(*p.space, *checker, ObprmSamplerSettings{100, 1000}, nullptr, &expired);
  core::Rng rng(6);
  State q;
  EXPECT_FALSE(o.sample(rng, q));
  EXPECT_LE(counters.cd_calls(), core::StopPoll::kStride);
  EXPECT_GT(counters.cd_calls(), 0u);
  const auto before = counters.cd_calls();
  EXPECT_FALSE(o.sample(rng, q));
  EXPECT_EQ(counters.cd_calls(), before);
  // Without a stop the same walk runs its course.
  core::Counters all;
  const auto unstopped = p.environment->make_checker(all);
  ObprmSampler free_run(*p.space, *unstopped, ObprmSamplerSettings{100, 1000});
  EXPECT_FALSE(free_run.sample(rng, q));
  EXPECT_GT(all.cd_calls(), core::StopPoll::kStride);
}

}  // namespace
}  // namespace amp::roadmap
