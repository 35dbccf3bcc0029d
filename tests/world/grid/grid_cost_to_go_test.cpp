#include "amp/world/grid_cost_to_go.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::world {
namespace {

const double kSqrt2 = std::sqrt(2.0);

// Rows written top (highest y) first, as they look on screen: '.' free, '#' blocked.
GridCells mask_of(const std::vector<std::string>& rows, double cell = 1.0) {
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows.front().size());
  GridCells m{w, h, cell, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h), 0), {}};
  for (int r = 0; r < h; ++r) {
    for (int x = 0; x < w; ++x) {
      m.free[static_cast<std::size_t>((h - 1 - r) * w + x)] = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(x)] == '.';
    }
  }
  return m;
}

// Length of a cell path, checking that every step is a legal move.
double length(const GridCostToGo& m, const std::vector<int>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int ax = path[i - 1] % m.cells().width, ay = path[i - 1] / m.cells().width;
    const int bx = path[i] % m.cells().width, by = path[i] / m.cells().width;
    const int dx = bx - ax, dy = by - ay;
    EXPECT_TRUE(std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dx != 0 || dy != 0));
    EXPECT_TRUE(m.free(bx, by));
    if (dx != 0 && dy != 0) {
      EXPECT_TRUE(m.free(ax + dx, ay) && m.free(ax, ay + dy)) << "corner cut at " << i;
    }
    sum += (dx != 0 && dy != 0 ? kSqrt2 : 1.0) * m.cells().cell_size;
  }
  return sum;
}

TEST(GridCostToGo, StraightCorridor) {
  GridCostToGo sp(mask_of({"##########", "..........", "##########"}, 0.5));
  sp.compute(sp.index(9, 1));
  const int start = sp.index(0, 1);
  EXPECT_DOUBLE_EQ(sp.distance(start), 4.5);
  const std::vector<int> p = sp.path(start);
  EXPECT_EQ(p.size(), 10u);
  EXPECT_EQ(p.front(), start);
  EXPECT_EQ(p.back(), sp.goal());
  EXPECT_DOUBLE_EQ(length(sp, p), 4.5);
}

TEST(GridCostToGo, OpenDiagonalAndNoCornerCutting) {
  GridCostToGo open(mask_of({"..", ".."}));
  open.compute(open.index(1, 0));
  EXPECT_DOUBLE_EQ(open.distance(open.index(0, 1)), kSqrt2);
  // (0, 0) blocked: the diagonal from (0, 1) to (1, 0) would cut its corner, so go round: 2.
  GridCostToGo cut(mask_of({"..", "#."}));
  cut.compute(cut.index(1, 0));
  EXPECT_DOUBLE_EQ(cut.distance(cut.index(0, 1)), 2.0);
  EXPECT_DOUBLE_EQ(length(cut, cut.path(cut.index(0, 1))), 2.0);
}

TEST(GridCostToGo, AroundAnLShapedWall) {
  // From (2, 2), in the L's inner corner, to (5, 1): up to (2, 4), along to (4, 4) (the wall's top
  // corner forbids the diagonal from (2, 3)), then 3 down and 1 right: 2 + 2 + 2 + sqrt(2).
  // With corner cutting it would be 2 + 3 sqrt(2).
  const GridCells m = mask_of({
      ".......",  // y = 4
      "...#...",  // y = 3
      "...#...",  // y = 2
      ".###...",  // y = 1
      ".......",  // y = 0
  });
  GridCostToGo sp(m);
  auto index = [&](int x, int y) { return sp.index(x, y); };
  sp.compute(index(5, 1));
  const int start = index(2, 2);
  EXPECT_NEAR(sp.distance(start), 6.0 + kSqrt2, 1e-12);
  const std::vector<int> p = sp.path(start);
  EXPECT_NEAR(length(sp, p), 6.0 + kSqrt2, 1e-12);
  EXPECT_EQ(p.back(), index(5, 1));
  // The universal plan: other starts read off the same field.
  EXPECT_DOUBLE_EQ(sp.distance(index(5, 1)), 0.0);
  EXPECT_NEAR(sp.distance(index(0, 0)), 4.0 + kSqrt2, 1e-12);  // 4 right to (4, 0), then one diagonal
}

TEST(GridCostToGo, UnreachablePocketsAreInfinite) {
  // The centre cell touches its free diagonal neighbours only at corners.
  const GridCells m = mask_of({
      ".#..",
      "#.#.",
      ".#..",
  });
  GridCostToGo sp(m);
  auto index = [&](int x, int y) { return sp.index(x, y); };
  sp.compute(index(3, 0));
  EXPECT_EQ(sp.distance(index(1, 1)), GridCostToGo::kUnreachable);
  EXPECT_TRUE(sp.path(index(1, 1)).empty());
  EXPECT_EQ(sp.distance(index(0, 0)), GridCostToGo::kUnreachable);
  EXPECT_EQ(sp.distance(index(1, 0)), GridCostToGo::kUnreachable);  // blocked
  EXPECT_DOUBLE_EQ(sp.distance(index(2, 2)), 3.0);  // (2, 1) blocks the diagonal to (3, 1)
  // Goal in the pocket: nothing else reaches it.
  sp.compute(index(1, 1));
  EXPECT_DOUBLE_EQ(sp.distance(index(1, 1)), 0.0);
  EXPECT_EQ(sp.distance(index(3, 0)), GridCostToGo::kUnreachable);
  // A blocked goal leaves every cell unreachable.
  sp.compute(index(1, 0));
  EXPECT_EQ(sp.distance(index(3, 0)), GridCostToGo::kUnreachable);
  EXPECT_THROW(sp.compute(99), ParameterError);
}

TEST(GridCostToGo, CellCostsByHand) {
  // A 3-cell corridor, costs 0, 2, 0: each straight step costs 1 * (1 + (0 + 2) / 2) = 2.
  GridCells c = mask_of({"..."});
  c.cost = {0.0, 2.0, 0.0};
  GridCostToGo sp(c);
  sp.compute(2);
  EXPECT_DOUBLE_EQ(sp.distance(1), 2.0);
  EXPECT_DOUBLE_EQ(sp.distance(0), 4.0);
  // Around a costly cell: in a 3 x 3 room with the centre at cost 10, from corner to corner one
  // straight step, one diagonal past the centre and one straight step (2 + sqrt(2)) beat the
  // diagonals through it (2 sqrt(2) (1 + 5) = 16.97).
  GridCells room = mask_of({"...", "...", "..."});
  room.cost.assign(9, 0.0);
  room.cost[4] = 10.0;
  GridCostToGo r(room);
  r.compute(8);
  EXPECT_DOUBLE_EQ(r.distance(0), 2.0 + kSqrt2);
  const std::vector<int> p = r.path(0);
  EXPECT_EQ(p.size(), 4u);
  EXPECT_TRUE(std::find(p.begin(), p.end(), 4) == p.end());
}

// Dijkstra with std::priority_queue, written independently of the bucket queue.
std::vector<double> reference_costs(const GridCells& c, int goal) {
  const int w = c.width, h = c.height;
  auto free = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && c.free[static_cast<std::size_t>(y * w + x)]; };
  std::vector<double> d(c.free.size(), GridCostToGo::kUnreachable);
  using E = std::pair<double, int>;
  std::priority_queue<E, std::vector<E>, std::greater<E>> q;
  if (!c.free[static_cast<std::size_t>(goal)]) return d;
  d[static_cast<std::size_t>(goal)] = 0.0;
  q.emplace(0.0, goal);
  while (!q.empty()) {
    const auto [dist, cell] = q.top();
    q.pop();
    if (dist > d[static_cast<std::size_t>(cell)]) continue;
    const int x = cell % w, y = cell / w;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !free(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && !(free(x + dx, y) && free(x, y + dy))) continue;
        const int n = (y + dy) * w + x + dx;
        const double len = (dx != 0 && dy != 0 ? kSqrt2 : 1.0) * c.cell_size;
        const double nd = dist + len * (1.0 + 0.5 * (c.cost[static_cast<std::size_t>(cell)] + c.cost[static_cast<std::size_t>(n)]));
        if (nd < d[static_cast<std::size_t>(n)]) d[static_cast<std::size_t>(n)] = nd, q.emplace(nd, n);
      }
    }
  }
  return d;
}

TEST(GridCostToGo, BucketQueueEqualsABinaryHeapOnRandomGrids) {
  std::mt19937 gen(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 5 + static_cast<int>(gen() % 40), h = 5 + static_cast<int>(gen() % 40);
    GridCells c{w, h, 0.05 + 0.1 * static_cast<double>(gen() % 10), std::vector<std::uint8_t>(static_cast<std::size_t>(w * h)), {}};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto& f : c.free) f = u(gen) < 0.7;
    c.cost.resize(c.free.size());
    for (auto& v : c.cost) v = trial % 2 == 0 ? 0.0 : 5.0 * u(gen);
    const int goal = static_cast<int>(gen() % c.free.size());
    GridCostToGo sp(c);
    sp.compute(goal);
    const std::vector<double> ref = reference_costs(c, goal);
    for (std::size_t i = 0; i < ref.size(); ++i) {
      if (ref[i] == GridCostToGo::kUnreachable) {
        EXPECT_EQ(sp.distance(static_cast<int>(i)), GridCostToGo::kUnreachable);
      } else {
        EXPECT_NEAR(sp.distance(static_cast<int>(i)), ref[i], 1e-9 * std::max(1.0, ref[i]));
      }
    }
  }
}

TEST(GridCostToGo, RejectsBadGrids) {
  GridCells c = mask_of({".."});
  c.cost = {0.0, -1.0};
  EXPECT_THROW(GridCostToGo{c}, ParameterError);
  c.cost = {0.0};
  EXPECT_THROW(GridCostToGo{c}, ParameterError);
  c.cost.clear();
  c.cell_size = 0.0;
  EXPECT_THROW(GridCostToGo{c}, ParameterError);
}

}  // namespace
}  // namespace amp::world
