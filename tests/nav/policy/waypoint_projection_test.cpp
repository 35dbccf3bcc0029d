#include "amp/nav/policy/waypoint_projection.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace amp::nav {
namespace {

constexpr double kPi = std::numbers::pi;

// A 10-wide grid of 0.5 m cells from (1, 2).
const GridFrame kFrame{10, 0.5, Eigen::Vector2d(1.0, 2.0)};
int cell(int x, int y) { return y * 10 + x; }

TEST(WaypointProjection, MergesNeighboursThatShareAnAction) {
  // East, east, north-east, north-east, north: three segments, four waypoints at cells 0, 2, 4, 5.
  const std::vector<int> path{cell(0, 0), cell(1, 0), cell(2, 0), cell(3, 1), cell(4, 2), cell(4, 3)};
  const Eigen::Vector2d start(1.2, 2.3), goal(3.3, 3.8);
  const std::vector<State> w = project_to_waypoints(path, kFrame, start, goal, 0.7);
  ASSERT_EQ(w.size(), 4u);
  // The start and the goal themselves; the inner waypoints at their cells' centres.
  EXPECT_DOUBLE_EQ(w[0][0], 1.2);
  EXPECT_DOUBLE_EQ(w[0][1], 2.3);
  EXPECT_DOUBLE_EQ(w[1][0], 1.0 + 0.5 * 2.5);  // cell (2, 0)
  EXPECT_DOUBLE_EQ(w[1][1], 2.0 + 0.5 * 0.5);
  EXPECT_DOUBLE_EQ(w[2][0], 1.0 + 0.5 * 4.5);  // cell (4, 2)
  EXPECT_DOUBLE_EQ(w[2][1], 2.0 + 0.5 * 2.5);
  EXPECT_DOUBLE_EQ(w[3][0], 3.3);
  EXPECT_DOUBLE_EQ(w[3][1], 3.8);
  // Headings along the segment each waypoint begins: start -> (2.25, 2.25); w1 -> w2 is (1, 1),
  // so pi/4; w2 = (3.25, 3.25) -> the goal (3.3, 3.8).
  EXPECT_NEAR(w[0][2], std::atan2(2.25 - 2.3, 2.25 - 1.2), 1e-12);
  EXPECT_NEAR(w[1][2], kPi / 4, 1e-12);
  EXPECT_NEAR(w[2][2], std::atan2(3.8 - 3.25, 3.3 - 3.25), 1e-12);
  EXPECT_NEAR(w[3][2], w[2][2], 1e-12);  // the last faces along the segment it ends
  for (const State& s : w) {
    EXPECT_DOUBLE_EQ(s[3], 0.7);
    EXPECT_DOUBLE_EQ(s[4], 0.0);
  }
}

TEST(WaypointProjection, StraightRunsAndDegenerateInputs) {
  // One action all along: only the two ends.
  const std::vector<int> line{cell(1, 1), cell(2, 1), cell(3, 1), cell(4, 1)};
  const std::vector<State> w = project_to_waypoints(line, kFrame, kFrame.center(line.front()), kFrame.center(line.back()), 1.0);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_DOUBLE_EQ(w[0][2], 0.0);
  EXPECT_DOUBLE_EQ(w[1][2], 0.0);
  // Start and goal in one cell.
  const std::vector<State> one = project_to_waypoints({cell(5, 5)}, kFrame, {3.6, 4.6}, {3.6, 4.9}, 1.0);
  ASSERT_EQ(one.size(), 2u);
  EXPECT_NEAR(one[0][2], kPi / 2, 1e-12);
  EXPECT_TRUE(project_to_waypoints({}, kFrame, {0, 0}, {1, 1}, 1.0).empty());
}

}  // namespace
}  // namespace amp::nav
