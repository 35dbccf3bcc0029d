#include "amp/nav/grid_nav_world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/world_event.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
const double kSqrt2 = std::sqrt(2.0);

// 10 x 10 cells of side 1 at the origin: a wall in column 5, rows 2..7; cell (7, 6); the diagonal
// pair (3, 7), (2, 8) that meets only at the corner (3, 8).
std::shared_ptr<world::OccupancyGrid> hand_map() {
  auto g = std::make_shared<world::OccupancyGrid>(10, 10, 1.0);
  for (int y = 2; y <= 7; ++y) g->set_state(5, y, world::CellState::kOccupied);
  g->set_state(7, 6, world::CellState::kOccupied);
  g->set_state(3, 7, world::CellState::kOccupied);
  g->set_state(2, 8, world::CellState::kUnknown);  // unknown counts as blocked
  return g;
}

TEST(GridNavWorld, RaysAcrossCells) {
  const GridNavWorld w(hand_map());
  EXPECT_DOUBLE_EQ(w.ray_cast({1.5, 4.5}, {1, 0}, 100), 3.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({1.5, 4.5}, {1, 0}, 2), 2.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({9.5, 4.5}, {-1, 0}, 100), 3.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({5.5, 0.5}, {0, 1}, 100), 1.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({0.5, 0.5}, {-1, 0}, 100), 0.5);  // the map's outside
  EXPECT_DOUBLE_EQ(w.ray_cast({0.5, 0.5}, {0, -1}, 100), 0.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({5.5, 4.5}, {1, 0}, 100), 0.0);   // in a blocked cell
  EXPECT_DOUBLE_EQ(w.ray_cast({6.0, 4.5}, {1, 0}, 100), 0.0);   // on its face
  EXPECT_DOUBLE_EQ(w.ray_cast({-1.0, 4.5}, {1, 0}, 100), 0.0);  // outside
  // A slanted ray: from (1.5, 4.5) at slope 1/2 it reaches x = 5 at y = 6.25, cell (5, 6).
  EXPECT_NEAR(w.ray_cast({1.5, 4.5}, V(2, 1).normalized(), 100), 3.5 * std::sqrt(1.25), 1e-12);
}

TEST(GridNavWorld, RaysAlongGridLinesTouchBothSides) {
  const GridNavWorld w(hand_map());
  // Along y = 2 the ray touches row 1 and row 2: the wall's lower corner at x = 5.
  EXPECT_DOUBLE_EQ(w.ray_cast({0.5, 2.0}, {1, 0}, 100), 4.5);
  // Along y = 1 nothing is touched until the border.
  EXPECT_DOUBLE_EQ(w.ray_cast({0.5, 1.0}, {1, 0}, 100), 9.5);
  // Along x = 8, cell (7, 6) on the left is touched at y = 6.
  EXPECT_DOUBLE_EQ(w.ray_cast({8.0, 0.5}, {0, 1}, 100), 5.5);
  // Along x = 9 upwards: nothing until the top border.
  EXPECT_DOUBLE_EQ(w.ray_cast({9.0, 0.5}, {0, 1}, 100), 9.5);
  // Along the map's border line the outside is touched at once.
  EXPECT_DOUBLE_EQ(w.ray_cast({0.0, 0.5}, {0, 1}, 100), 0.0);
}

TEST(GridNavWorld, RaysThroughCorners) {
  const GridNavWorld w(hand_map());
  // The 45 degree ray from (1.5, 6.5) passes the corners (2, 7) and (3, 8); at (3, 8) it slips
  // between the diagonal pair (3, 7) and (2, 8), which touch it there.
  EXPECT_NEAR(w.ray_cast({1.5, 6.5}, V(1, 1).normalized(), 100), 1.5 * kSqrt2, 1e-12);
  // Up-left from (7.5, 0.5): the corner (6, 2) leads into the wall cell (5, 2).
  EXPECT_NEAR(w.ray_cast({7.5, 0.5}, V(-1, 1).normalized(), 100), 1.5 * kSqrt2, 1e-12);
  // Corners with nothing blocked around them are passed, up to the wall's corner (5, 5).
  EXPECT_NEAR(w.ray_cast({0.5, 0.5}, V(1, 1).normalized(), 100), 4.5 * kSqrt2, 1e-12);
}

// Exact answer by brute force: the first closed square (or border) the ray meets.
double brute_ray(const world::OccupancyGrid& g, const V& p, const V& d, double max_range) {
  const auto entry = [&](const Eigen::AlignedBox2d& box) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 2; ++k) {
      if (d[k] == 0.0) {
        if (p[k] < box.min()[k] || p[k] > box.max()[k]) return std::numeric_limits<double>::infinity();
        continue;
      }
      double a = (box.min()[k] - p[k]) / d[k], b = (box.max()[k] - p[k]) / d[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
  };
  double best = max_range;
  const Eigen::AlignedBox2d e = g.extent();
  for (int k = 0; k < 2; ++k) {
    if (d[k] > 0) best = std::min(best, (e.max()[k] - p[k]) / d[k]);
    if (d[k] < 0) best = std::min(best, (e.min()[k] - p[k]) / d[k]);
  }
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (g.blocked(x, y)) best = std::min(best, entry(g.cell_box(x, y)));
    }
  }
  return best;
}

TEST(GridNavWorld, RaysEqualBruteForceOnARandomMap) {
  core::Rng rng(3);
  auto g = std::make_shared<world::OccupancyGrid>(24, 16, 0.25, V(-2.0, 1.0));
  for (int y = 0; y < g->height(); ++y) {
    for (int x = 0; x < g->width(); ++x) {
      if (rng.uniform01() < 0.15) g->set_state(x, y, world::CellState::kOccupied);
    }
  }
  const GridNavWorld w(g);
  const Eigen::AlignedBox2d e = g->extent();
  int checked = 0;
  for (int i = 0; i < 500; ++i) {
    const V p(rng.uniform(e.min().x(), e.max().x()), rng.uniform(e.min().y(), e.max().y()));
    if (!w.disc_free(p, 0.0)) continue;
    const double a = rng.uniform(0, 2 * M_PI);
    const V d(std::cos(a), std::sin(a));
    EXPECT_NEAR(w.ray_cast(p, d, 4.0), brute_ray(*g, p, d, 4.0), 1e-9) << i;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(GridNavWorld, NearestObstacleAndDiscs) {
  const GridNavWorld w(hand_map());
  const NearestObstacle n = w.nearest_obstacle({3.5, 4.5});
  EXPECT_DOUBLE_EQ(n.distance, 1.5);
  EXPECT_TRUE(n.point.isApprox(V(5, 4.5)));
  EXPECT_DOUBLE_EQ(w.nearest_obstacle({0.25, 4.5}).distance, 0.25);  // the outside
  EXPECT_DOUBLE_EQ(w.nearest_obstacle({5.5, 4.5}).distance, 0.0);
  // The corner (6, 8) of the wall's top cell from (6.5, 8.5): sqrt(0.5).
  EXPECT_NEAR(w.nearest_obstacle({6.5, 8.5}).distance, std::sqrt(0.5), 1e-12);
  EXPECT_TRUE(w.disc_free({3.5, 4.5}, 1.5));
  EXPECT_FALSE(w.disc_free({3.5, 4.5}, 1.51));
  EXPECT_FALSE(w.disc_free({0.4, 4.5}, 0.5));
}

TEST(GridNavWorld, ChangesSetCellsAndRasteriseShapes) {
  const GridNavWorld w(hand_map());
  ObstacleChange close;
  close.cells.push_back({2, 4, 2, 5});
  const auto closed = w.changed(close);
  EXPECT_DOUBLE_EQ(closed->ray_cast({0.5, 4.5}, {1, 0}, 100), 1.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({0.5, 4.5}, {1, 0}, 100), 4.5);
  ObstacleChange open;
  open.action = ObstacleChange::Action::kVanish;
  open.shapes.polygons.push_back({{{5, 4}, {6, 4}, {6, 5}, {5, 5}}});  // exactly cell (5, 4)
  const auto opened = w.changed(open);
  EXPECT_DOUBLE_EQ(opened->ray_cast({0.5, 4.5}, {1, 0}, 100), 9.5);
  EXPECT_DOUBLE_EQ(opened->ray_cast({0.5, 3.5}, {1, 0}, 100), 4.5);  // (5, 3) stays
  ObstacleChange disc;
  disc.shapes.circles.push_back({{1.5, 1.5}, 0.4});  // inside cell (1, 1) only
  const auto with_disc = w.changed(disc);
  EXPECT_DOUBLE_EQ(with_disc->ray_cast({0.5, 1.5}, {1, 0}, 100), 0.5);
  EXPECT_DOUBLE_EQ(with_disc->ray_cast({0.5, 2.5}, {1, 0}, 100), 4.5);
  ObstacleChange bad;
  bad.cells.push_back({8, 8, 10, 9});
  EXPECT_THROW(w.changed(bad), ParameterError);
}

}  // namespace
}  // namespace amp::nav
