// SINS's control loop runs every step: the motor schemas, the trends and the adaptive system's
// cycle (perceive, retrieve, adapt, learn) must not touch the heap, apart from a created case's two
// vectors (sins-plus: a split case's two windows). Global operator new is replaced by a counting
// one in this executable.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"

#include <array>
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/nav/sins/environment_trends.hpp"
#include "amp/nav/sins/motor_schemas.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/sins/sins_plus_parameters.hpp"

namespace amp::nav {
namespace {

TEST(SinsCycleAllocation, StepsAndIntervalsAllocateOnlyForCreatedCases) {
  for (const double outcome_rate : {0.0, 0.5}) {  // the interval rule, and the outcome credit
    SCOPED_TRACE(outcome_rate);
    learn::CaseSettings cs;
    cs.case_length = 20;
    cs.max_cases = 10;
    cs.outcome_rate = outcome_rate;
    CaseBasedParameters sins(cs);
    MotorSchemas schemas;
    EnvironmentTrends trends(2.0, 1.0);
    core::Rng rng(4);
    std::vector<double> readings(16);
    std::vector<Eigen::Vector2d> directions(16);
    for (int i = 0; i < 16; ++i) directions[i] = Eigen::Vector2d(std::cos(i * 0.3927), std::sin(i * 0.3927));
    Eigen::Vector2d position(1, 1);
    const Eigen::Vector2d goal(30, 30);
    SchemaParameters p = sins.begin_world(rng);
    trends.reset(position, goal);
    const long before = amp::test::allocations();
    long created = 0;
    for (int step = 1; step <= 6000; ++step) {
      const double regime = (step / 600) % 3;  // three kinds of surroundings in turn
      for (double& r : readings) r = rng.uniform(0.1 * regime, 2.0);
      position += schemas.velocity(position, goal, readings, directions, p, rng);
      trends.step(readings, position);
      if (step % 12 == 0) {
        const int cases = sins.cases();
        p = sins.end_interval(trends.close_interval(), rng);
        created += sins.cases() - cases;
      }
      if (step % 500 == 0) {  // a world ends, solved every other time, and the next begins
        sins.end_world(step % 1000 == 0, 0.5);
        p = sins.begin_world(rng);
      }
    }
    EXPECT_EQ(amp::test::allocations() - before, 2 * created);
  }
}

// sins-plus's cycle (reward, retrieve, explore, and the fits) allocates only when a case splits: the
// new case's window and the old one's, rebuilt.
TEST(SinsCycleAllocation, SinsPlusAllocatesOnlyForSplits) {
  learn::SplittingCaseSettings ps;
  ps.horizon = 4;
  ps.split_t = 0.5;  // eager splits, so that some happen here
  SplittingCaseParameters plus(ps);
  core::Rng rng(5);
  const long before = amp::test::allocations();
  long created = 0;
  for (int interval = 1; interval <= 3000; ++interval) {
    const double regime = (interval / 50) % 3;
    const learn::CaseInputs in{0.3 * regime, rng.uniform01(), 0.5, rng.uniform(0.2 * regime, 1.0)};
    const int cases = plus.cases();
    plus.end_interval(in, rng);
    if (interval % 40 == 0) {  // the world's end credits what is pending, which can split too
      plus.end_world(interval % 80 == 0, 0.5);
      plus.begin_world(rng);
    }
    created += plus.cases() - cases;
  }
  EXPECT_GT(created, 0);
  EXPECT_EQ(amp::test::allocations() - before, 2 * created);
}

}  // namespace
}  // namespace amp::nav
