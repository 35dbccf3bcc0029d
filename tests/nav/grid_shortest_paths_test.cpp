#include "amp/nav/grid_shortest_paths.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::nav {
namespace {

const double kSqrt2 = std::sqrt(2.0);

// Rows written top (highest y) first, as they look on screen: '.' free, '#' blocked.
FreeMask mask_of(const std::vector<std::string>& rows, double cell = 1.0) {
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows.front().size());
  FreeMask m(w, h, cell);
  for (int r = 0; r < h; ++r) {
    for (int x = 0; x < w; ++x) m.set_free(x, h - 1 - r, rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(x)] == '.');
  }
  return m;
}

// Length of a cell path, checking that every step is a legal move.
double length(const FreeMask& m, const std::vector<int>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int ax = path[i - 1] % m.width(), ay = path[i - 1] / m.width();
    const int bx = path[i] % m.width(), by = path[i] / m.width();
    const int dx = bx - ax, dy = by - ay;
    EXPECT_TRUE(std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dx != 0 || dy != 0));
    EXPECT_TRUE(m.free(bx, by));
    if (dx != 0 && dy != 0) {
      EXPECT_TRUE(m.free(ax + dx, ay) && m.free(ax, ay + dy)) << "corner cut at " << i;
    }
    sum += (dx != 0 && dy != 0 ? kSqrt2 : 1.0) * m.cell_size();
  }
  return sum;
}

TEST(GridShortestPaths, StraightCorridor) {
  GridShortestPaths sp(mask_of({"##########", "..........", "##########"}, 0.5));
  sp.compute(sp.mask().index(9, 1));
  const int start = sp.mask().index(0, 1);
  EXPECT_DOUBLE_EQ(sp.distance(start), 4.5);
  const std::vector<int> p = sp.path(start);
  EXPECT_EQ(p.size(), 10u);
  EXPECT_EQ(p.front(), start);
  EXPECT_EQ(p.back(), sp.goal());
  EXPECT_DOUBLE_EQ(length(sp.mask(), p), 4.5);
}

TEST(GridShortestPaths, OpenDiagonalAndNoCornerCutting) {
  GridShortestPaths open(mask_of({"..", ".."}));
  open.compute(open.mask().index(1, 0));
  EXPECT_DOUBLE_EQ(open.distance(open.mask().index(0, 1)), kSqrt2);
  // (0, 0) blocked: the diagonal from (0, 1) to (1, 0) would cut its corner, so go round: 2.
  GridShortestPaths cut(mask_of({"..", "#."}));
  cut.compute(cut.mask().index(1, 0));
  EXPECT_DOUBLE_EQ(cut.distance(cut.mask().index(0, 1)), 2.0);
  EXPECT_DOUBLE_EQ(length(cut.mask(), cut.path(cut.mask().index(0, 1))), 2.0);
}

TEST(GridShortestPaths, AroundAnLShapedWall) {
  // From (2, 2), in the L's inner corner, to (5, 1): up to (2, 4), along to (4, 4) (the wall's top
  // corner forbids the diagonal from (2, 3)), then 3 down and 1 right: 2 + 2 + 2 + sqrt(2).
  // With corner cutting it would be 2 + 3 sqrt(2).
  const FreeMask m = mask_of({
      ".......",  // y = 4
      "...#...",  // y = 3
      "...#...",  // y = 2
      ".###...",  // y = 1
      ".......",  // y = 0
  });
  GridShortestPaths sp(m);
  sp.compute(m.index(5, 1));
  const int start = m.index(2, 2);
  EXPECT_NEAR(sp.distance(start), 6.0 + kSqrt2, 1e-12);
  const std::vector<int> p = sp.path(start);
  EXPECT_NEAR(length(m, p), 6.0 + kSqrt2, 1e-12);
  EXPECT_EQ(p.back(), m.index(5, 1));
  // The universal plan: other starts read off the same field.
  EXPECT_DOUBLE_EQ(sp.distance(m.index(5, 1)), 0.0);
  EXPECT_NEAR(sp.distance(m.index(0, 0)), 4.0 + kSqrt2, 1e-12);  // 4 right to (4, 0), then one diagonal
}

TEST(GridShortestPaths, UnreachablePocketsAreInfinite) {
  // The centre cell touches its free diagonal neighbours only at corners.
  const FreeMask m = mask_of({
      ".#..",
      "#.#.",
      ".#..",
  });
  GridShortestPaths sp(m);
  sp.compute(m.index(3, 0));
  EXPECT_EQ(sp.distance(m.index(1, 1)), GridShortestPaths::kUnreachable);
  EXPECT_TRUE(sp.path(m.index(1, 1)).empty());
  EXPECT_EQ(sp.distance(m.index(0, 0)), GridShortestPaths::kUnreachable);
  EXPECT_EQ(sp.distance(m.index(1, 0)), GridShortestPaths::kUnreachable);  // blocked
  EXPECT_DOUBLE_EQ(sp.distance(m.index(2, 2)), 3.0);  // (2, 1) blocks the diagonal to (3, 1)
  // Goal in the pocket: nothing else reaches it.
  sp.compute(m.index(1, 1));
  EXPECT_DOUBLE_EQ(sp.distance(m.index(1, 1)), 0.0);
  EXPECT_EQ(sp.distance(m.index(3, 0)), GridShortestPaths::kUnreachable);
  // A blocked goal leaves every cell unreachable.
  sp.compute(m.index(1, 0));
  EXPECT_EQ(sp.distance(m.index(3, 0)), GridShortestPaths::kUnreachable);
  EXPECT_THROW(sp.compute(99), ParameterError);
}

}  // namespace
}  // namespace amp::nav
