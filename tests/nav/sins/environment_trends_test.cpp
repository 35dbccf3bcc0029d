#include "amp/nav/sins/environment_trends.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

TEST(EnvironmentTrends, AnIntervalByHand) {
  // Sphere 2 m, 1 m per step at most; goal 10 m east of the start.
  EnvironmentTrends t(2.0, 1.0);
  t.reset(V(0, 0), V(10, 0));
  // Step 1: readings 0.5 and 2.5 (clipped to 2): density (0.75 + 0) / 2 = 0.375; east 1 m.
  t.step(std::vector<double>{0.5, 2.5}, V(1, 0));
  // Step 2: readings 1 and 1: density 0.5; north 1 m (no progress).
  t.step(std::vector<double>{1.0, 1.0}, V(1, 1));
  const auto in = t.close_interval();
  EXPECT_DOUBLE_EQ(in[0], (0.375 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(in[1], 1.0);                   // 2 m driven of 2 possible
  EXPECT_DOUBLE_EQ(in[2], 0.5 * (1.0 - 0.0 + 1.0));  // from 0 before
  // Progress: 10 - |(10, 0) - (1, 1)| = 10 - sqrt(82), over 2 m.
  EXPECT_NEAR(in[3], 0.5 * ((10.0 - std::sqrt(82.0)) / 2.0 + 1.0), 1e-12);
  // Next interval: one step back west 0.5 m, no readings.
  t.step(std::vector<double>{}, V(0.5, 1));
  const auto next = t.close_interval();
  EXPECT_DOUBLE_EQ(next[0], 0.0);
  EXPECT_DOUBLE_EQ(next[1], 0.5);
  EXPECT_DOUBLE_EQ(next[2], 0.5 * (0.5 - 1.0 + 1.0));
  EXPECT_NEAR(next[3], 0.5 * ((std::sqrt(82.0) - std::sqrt(91.25)) / 1.0 + 1.0), 1e-12);
  // An empty interval.
  const auto none = t.close_interval();
  EXPECT_EQ(none, (std::array<double, 4>{0.0, 0.0, 0.5, 0.5}));
  EXPECT_THROW(EnvironmentTrends(0.0, 1.0), ParameterError);
  EXPECT_THROW(EnvironmentTrends(1.0, -1.0), ParameterError);
}

}  // namespace
}  // namespace amp::nav
