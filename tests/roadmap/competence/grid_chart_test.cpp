// competence/grid_chart.cpp: the flat coordinates (grid steps, offsets from an origin) the A* local
// planner searches in, and their way back to states.
#include "amp/roadmap/competence/grid_chart.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/core/unicycle_space.hpp"

namespace amp::roadmap {
namespace {

constexpr double kPi = std::numbers::pi;

State state(std::initializer_list<double> v) {
  State s(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) s[i++] = x;
  return s;
}

TEST(GridChart, RnStepsAreTheRangeOverStepsAndCoordinatesAreOffsets) {
  const core::JointSpace space = core::make_rn_space({0, -2}, {10, 2});
  GridChart chart(space, 8);
  ASSERT_EQ(chart.dimension(), 2);
  EXPECT_DOUBLE_EQ(chart.step(0), 10.0 / 8.0);
  EXPECT_DOUBLE_EQ(chart.step(1), 4.0 / 8.0);
  chart.set_origin(state({2, 1}));
  double x[2];
  chart.coordinates(state({5, -0.5}), x);
  EXPECT_DOUBLE_EQ(x[0], 3.0);
  EXPECT_DOUBLE_EQ(x[1], -1.5);
  // Cell (i, j) of the grid around the origin: origin + (i * step0, j * step1).
  State s;
  const double cell[2] = {3 * chart.step(0), -2 * chart.step(1)};
  ASSERT_TRUE(chart.state_at(cell, s));
  EXPECT_EQ(s, state({2 + 3.75, 1 - 1.0}));
  // Off the space's bounds: x = 2 + 9 > 10, y = 1 + 1.5 > 2; the bounds themselves are inside.
  const double past_x[2] = {9.0, 0.0}, past_y[2] = {0.0, 1.5}, edge[2] = {8.0, 1.0};
  EXPECT_FALSE(chart.state_at(past_x, s));
  EXPECT_FALSE(chart.state_at(past_y, s));
  EXPECT_TRUE(chart.state_at(edge, s));
  EXPECT_EQ(s, state({10, 2}));
}

TEST(GridChart, ContinuousAnglesGoTheShortWayRoundAndWrap) {
  // SE2: x, y linear; theta continuous with a grid step of 2 pi / steps whatever its weight.
  const core::JointSpace space = core::make_se2_space(0, 0, 4, 4, 0.7);
  GridChart chart(space, 16);
  ASSERT_EQ(chart.dimension(), 3);
  EXPECT_DOUBLE_EQ(chart.step(0), 0.25);
  EXPECT_DOUBLE_EQ(chart.step(2), 2 * kPi / 16);
  chart.set_origin(state({1, 1, 3.0}));
  double x[3];
  chart.coordinates(state({1, 1, -3.0}), x);
  EXPECT_NEAR(x[2], 2 * kPi - 6.0, 1e-12);  // +0.283 across pi, not -6
  chart.coordinates(state({1, 1, 2.0}), x);
  EXPECT_NEAR(x[2], -1.0, 1e-12);
  // A step past pi comes back wrapped into (-pi, pi]; angles never leave the space.
  State s;
  const double across[3] = {0.0, 0.0, 0.5};
  ASSERT_TRUE(chart.state_at(across, s));
  EXPECT_NEAR(s[2], 3.5 - 2 * kPi, 1e-12);
  const double many_turns[3] = {0.0, 0.0, 10 * kPi + 0.5};
  ASSERT_TRUE(chart.state_at(many_turns, s));
  EXPECT_NEAR(s[2], 3.5 - 2 * kPi, 1e-9);
}

TEST(GridChart, CellsAndStatesRoundTripOnALinkage) {
  const core::JointSpace space("linkage", {{"a", core::JointKind::kContinuous, 0, 0, 1.0},
                                           {"b", core::JointKind::kRevolute, -2.5, 2.5, 1.0},
                                           {"c", core::JointKind::kLinear, 0, 1, 1.0}});
  GridChart chart(space, 32);
  EXPECT_DOUBLE_EQ(chart.step(0), 2 * kPi / 32);
  EXPECT_DOUBLE_EQ(chart.step(1), 5.0 / 32);
  EXPECT_DOUBLE_EQ(chart.step(2), 1.0 / 32);
  chart.set_origin(state({-3.0, 0.5, 0.5}));
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) {
      const double cell[3] = {i * chart.step(0), j * chart.step(1), (i + j) * chart.step(2)};
      State s;
      ASSERT_TRUE(chart.state_at(cell, s));
      EXPECT_TRUE(space.in_bounds(s));
      double back[3];
      chart.coordinates(s, back);
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(back[d], cell[d], 1e-12) << i << " " << j << " axis " << d;
    }
  }
}

TEST(GridChart, Se3TranslationThenRotationVectorAtTheOrigin) {
  const core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(8, 4, 2), 1.0);
  GridChart chart(space, 16);
  ASSERT_EQ(chart.dimension(), 6);
  EXPECT_DOUBLE_EQ(chart.step(0), 0.5);
  EXPECT_DOUBLE_EQ(chart.step(1), 0.25);
  EXPECT_DOUBLE_EQ(chart.step(2), 0.125);
  for (int i = 3; i < 6; ++i) EXPECT_DOUBLE_EQ(chart.step(i), 2 * kPi / 16);
  // Origin turned a quarter about z; s turned a further 0.3 about the origin's own x axis.
  const Eigen::Quaterniond o(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  chart.set_origin(core::Se3Space::make_state(Eigen::Vector3d(4, 2, 1), o));
  const Eigen::Quaterniond q = o * Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  double x[6];
  chart.coordinates(core::Se3Space::make_state(Eigen::Vector3d(5, 1.5, 1), q), x);
  const double want[6] = {1.0, -0.5, 0.0, 0.3, 0.0, 0.0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(x[i], want[i], 1e-12) << i;
  State s;
  ASSERT_TRUE(chart.state_at(want, s));
  EXPECT_NEAR(s[0], 5.0, 1e-12);
  EXPECT_NEAR(s[1], 1.5, 1e-12);
  EXPECT_NEAR(core::Se3Space::rotation(s).angularDistance(q), 0.0, 1e-9);
  const double below[6] = {0, 0, -1.5, 0, 0, 0};  // z = -0.5 < 0
  EXPECT_FALSE(chart.state_at(below, s));
}

TEST(GridChart, RefusesNoSteps) {
  const core::JointSpace space = core::make_rn_space({0}, {1});
  EXPECT_THROW(GridChart(space, 0), ParameterError);
  EXPECT_NO_THROW(GridChart(space, 1));
}

// The unicycle offers no coordinate layout (core::Space::coordinate_layout): one line naming it.
TEST(GridChart, RefusesASpaceWithoutACoordinateLayout) {
  const core::UnicycleSpace space({.x_min = 0, .x_max = 1, .y_min = 0, .y_max = 1, .v_min = 0, .v_max = 1,
                                   .omega_min = -1, .omega_max = 1});
  try {
    GridChart chart(space, 4);
    FAIL() << "a unicycle space was charted";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "grid: no grid chart for a 'unicycle' space");
  }
}

}  // namespace
}  // namespace amp::roadmap
