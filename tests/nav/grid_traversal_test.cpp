#include "amp/nav/grid_traversal.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace amp::nav {
namespace {

std::vector<std::pair<int, int>> cells(const Eigen::Vector2d& origin, const Eigen::Vector2d& dir, int n) {
  GridTraversal walk(origin, dir);
  std::vector<std::pair<int, int>> out{{walk.x(), walk.y()}};
  for (int i = 1; i < n; ++i) {
    walk.next();
    out.emplace_back(walk.x(), walk.y());
  }
  return out;
}

TEST(GridTraversal, WalksAShallowRayCellByCell) {
  // From (0.5, 0.5) towards (3.5, 1.5): crosses x = 1, x = 2 (at y = 1.1667), y = 1 at x = 2 + ...
  const Eigen::Vector2d d = Eigen::Vector2d(3.0, 1.0).normalized();
  const auto c = cells({0.5, 0.5}, d, 5);
  const std::vector<std::pair<int, int>> want{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1}};
  EXPECT_EQ(c, want);
}

TEST(GridTraversal, ExitTimesAreDistancesAlongTheRay) {
  GridTraversal walk({0.5, 0.5}, {1.0, 0.0});
  EXPECT_DOUBLE_EQ(walk.t_exit(), 0.5);
  walk.next();
  EXPECT_DOUBLE_EQ(walk.t_exit(), 1.5);
  EXPECT_EQ(walk.y(), 0);
  GridTraversal scaled({0.5, 0.5}, {0.0, 2.0});  // two cells per unit of t
  EXPECT_DOUBLE_EQ(scaled.t_exit(), 0.25);
}

TEST(GridTraversal, DiagonalThroughCornersStepsBothAxes) {
  GridTraversal walk({0.5, 0.5}, Eigen::Vector2d(-1.0, -1.0).normalized());
  EXPECT_EQ(walk.next(), GridTraversal::Crossing::kCorner);
  EXPECT_EQ(walk.x(), -1);
  EXPECT_EQ(walk.y(), -1);
  EXPECT_NEAR(walk.t_exit(), 1.5 * std::sqrt(2.0), 1e-12);
}

TEST(GridTraversal, PointOnABorderMovingDownCrossesAtOnce) {
  GridTraversal walk({2.0, 0.5}, {-1.0, 0.0});
  EXPECT_EQ(walk.x(), 2);
  EXPECT_DOUBLE_EQ(walk.t_exit(), 0.0);
  walk.next();
  EXPECT_EQ(walk.x(), 1);
  EXPECT_DOUBLE_EQ(walk.t_exit(), 1.0);
}

}  // namespace
}  // namespace amp::nav
