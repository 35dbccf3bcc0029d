#include "amp/nav/pgcs/trace_corridor.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

// A 20 x 20 raster of 1 m cells from (0, 0).
TraceCorridor open_raster() { return TraceCorridor(FreeMask(20, 20, 1.0)); }

double length(const std::vector<V>& path) {
  double l = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) l += (path[i] - path[i - 1]).norm();
  return l;
}

const auto kAll = [](int) { return true; };

// No point of a shortened leg comes within half a cell of the middle of an unvisited cell (the
// legs between neighbouring cells' kept positions, not shortened, are not held to it).
void expect_clear_of_unvisited(const TraceCorridor& t, const std::vector<V>& path) {
  const FreeMask& g = t.geometry();
  for (std::size_t i = 1; i < path.size(); ++i) {
    if ((path[i] - path[i - 1]).norm() <= 1.5 * g.cell_size()) continue;
    for (double s = 0.0; s <= 1.0; s += 0.01) {
      const V p = path[i - 1] + s * (path[i] - path[i - 1]);
      for (int c = 0; c < static_cast<int>(g.cell_count()); ++c) {
        if (t.visited(c)) continue;
        EXPECT_GT((p - g.cell_center(c)).norm(), 0.5 * g.cell_size() - 1e-9)
            << "leg " << i << " at " << p.transpose() << " near unvisited cell " << c;
      }
    }
  }
}

TEST(TraceCorridor, AStepMarksEveryCellItCrossesWithAPointOfTheStep) {
  TraceCorridor t = open_raster();
  t.visit(V(0.5, 0.5), V(3.5, 0.5));  // cells (0..3, 0)
  EXPECT_EQ(t.visited_count(), 4u);
  t.visit(V(3.5, 0.5), V(4.5, 1.2));  // a slanted step into (4, 1), through (4, 0): not corner to corner
  EXPECT_TRUE(t.visited(t.geometry().index(4, 1)));
  EXPECT_TRUE(t.visited(t.geometry().index(4, 0)));
  EXPECT_FALSE(t.visited(t.geometry().index(3, 1)));
  EXPECT_EQ(t.visited_count(), 6u);
  t.visit(V(-1, -1));  // outside: nothing
  EXPECT_FALSE(t.visited(-1));
}

TEST(TraceCorridor, PathFollowsTheTraceRoundWhatWasNeverVisited) {
  // An L: along y = 0.5 to x = 10.5, then up to y = 10.5. Nothing inside the L was visited (a wall,
  // as far as the robot knows), so the way from one end to the other goes round the corner.
  TraceCorridor t = open_raster();
  t.visit(V(0.5, 0.5), V(10.5, 0.5));
  t.visit(V(10.5, 0.5), V(10.5, 10.5));
  const std::vector<V> path = t.path(V(0.5, 0.5), V(10.5, 10.5), 0.0, kAll);
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path.front(), V(0.5, 0.5));
  EXPECT_EQ(path.back(), V(10.5, 10.5));
  // Along the L, cutting its corner by no more than the clear band allows.
  EXPECT_GT(length(path), 19.0);
  EXPECT_LT(length(path), 20.0);
  expect_clear_of_unvisited(t, path);
  // With the inside visited too, the way is the straight diagonal.
  for (int y = 0; y < 12; ++y) t.visit(V(0.5, y + 0.5), V(11.5, y + 0.5));
  EXPECT_NEAR(length(t.path(V(0.5, 0.5), V(10.5, 10.5), 0.0, kAll)), std::sqrt(200.0), 1e-9);
}

TEST(TraceCorridor, PathKeepsToTheAllowedCellsAndFailsWithoutThem) {
  TraceCorridor t = open_raster();
  t.visit(V(0.5, 0.5), V(10.5, 0.5));
  const auto left_half = [&](int cell) { return cell % 20 < 6; };
  EXPECT_TRUE(t.path(V(0.5, 0.5), V(10.5, 0.5), 0.0, left_half).empty());
  const std::vector<V> along = t.path(V(0.5, 0.5), V(5.5, 0.5), 0.0, left_half);
  ASSERT_FALSE(along.empty());
  EXPECT_NEAR(length(along), 5.0, 1e-9);
  for (const V& p : along) EXPECT_EQ(p.y(), 0.5);  // on the trace: nothing beside it is known
  EXPECT_TRUE(t.path(V(0.5, 0.5), V(30.0, 0.5), 0.0, kAll).empty());     // an end outside the raster
}

TEST(TraceCorridor, AnUnvisitedEndIsJoinedWithinReachOnly) {
  TraceCorridor t = open_raster();
  t.visit(V(0.5, 0.5), V(10.5, 0.5));
  EXPECT_TRUE(t.path(V(0.5, 0.5), V(10.5, 4.5), 2.0, kAll).empty());  // 4 m from the trace
  const std::vector<V> path = t.path(V(0.5, 0.5), V(10.5, 2.5), 2.0, kAll);  // 2 m: guessed
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.back(), V(10.5, 2.5));
  TraceCorridor u = open_raster();
  u.visit(V(0.5, 0.5), V(5.5, 0.5));
  u.visit(V(0.5, 2.5), V(5.5, 2.5));  // a second corridor 2 m away, never joined
  EXPECT_TRUE(u.path(V(5.5, 0.5), V(5.5, 2.5), 2.0, kAll).empty());  // visited ends: no guess round them
}

TEST(TraceCorridor, ForgottenCellsCutTheWay) {
  TraceCorridor t = open_raster();
  t.visit(V(0.5, 0.5), V(10.5, 0.5));
  const std::uint64_t before = t.version();
  t.forget(V(5.5, 0.5), 1.0);  // cells 4, 5, 6 (centres within 1 m)
  EXPECT_EQ(t.visited_count(), 8u);
  EXPECT_NE(t.version(), before);
  EXPECT_TRUE(t.path(V(0.5, 0.5), V(10.5, 0.5), 0.0, kAll).empty());
  t.visit(V(3.5, 0.5), V(7.5, 0.5));  // driven again: known again
  EXPECT_NEAR(length(t.path(V(0.5, 0.5), V(10.5, 0.5), 0.0, kAll)), 10.0, 1e-9);
}

TEST(TraceCorridor, FirstUnreachedNamesTheRouteStepTheTraceDoesNotJoin) {
  // Labels by column band: 0 for x < 5, 1 for 5 <= x < 10, 2 beyond. The trace joins bands 0 and 1
  // along y = 0.5, and reaches band 2 only at y = 10.5, from band 1's column x = 9.
  TraceCorridor t = open_raster();
  const auto label = [](int cell) { return (cell % 20) < 5 ? 0 : (cell % 20) < 10 ? 1 : 2; };
  t.visit(V(0.5, 0.5), V(9.5, 0.5));
  t.visit(V(9.5, 0.5), V(9.5, 10.5));
  t.visit(V(9.5, 10.5), V(15.5, 10.5));
  const V from(0.5, 0.5), to(15.5, 10.5);
  EXPECT_EQ(t.first_unreached(from, to, 0.0, 0, {1, 2}, label), 3u);  // every step joined, and the target
  EXPECT_EQ(t.first_unreached(from, to, 0.0, 0, {2}, label), 0u);     // 0 -> 2 directly: not joined
  EXPECT_EQ(t.first_unreached(from, to, 0.0, 0, {1}, label), 1u);     // 1 reached, the target not
  t.forget(V(9.5, 5.5), 0.6);
  EXPECT_EQ(t.first_unreached(from, to, 0.0, 0, {1, 2}, label), 1u);  // the climb is cut: 2 not reached
}

TEST(TraceCorridor, ShortenedLegsKeepAClearBandFromUnknownCells) {
  // A trace along the edge of what was visited: the shortened legs may cut the corner of the
  // unvisited block, but come no nearer than half a cell to the middle of an unvisited cell.
  TraceCorridor t = open_raster();
  for (int y = 0; y < 3; ++y) t.visit(V(0.5, y + 0.5), V(12.5, y + 0.5));   // a band along the bottom
  for (int x = 10; x < 13; ++x) t.visit(V(x + 0.5, 0.5), V(x + 0.5, 12.5));  // a band up the right
  const std::vector<V> path = t.path(V(1.5, 1.5), V(11.5, 11.5), 0.0, kAll);
  ASSERT_GE(path.size(), 3u);
  EXPECT_LT(length(path), 10.0 + 10.0);  // shortened: less than the two straight runs
  expect_clear_of_unvisited(t, path);
}

}  // namespace
}  // namespace amp::nav
