#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include "amp/core/error.hpp"
#include "amp/world/grid_environment.hpp"

namespace amp::world {
namespace {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;
using BBox = bg::model::box<BPoint>;

// A 30 x 20 map at 0.1 m with an offset origin: random occupied and unknown cells plus a wall.
std::shared_ptr<OccupancyGrid> random_grid(unsigned seed, double density = 0.08) {
  auto g = std::make_shared<OccupancyGrid>(30, 20, 0.1, Eigen::Vector2d(-1.0, 0.5));
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int y = 0; y < g->height(); ++y) {
    for (int x = 0; x < g->width(); ++x) {
      const double r = u(gen);
      if (r < 0.75 * density) g->set_state(x, y, CellState::kOccupied);
      else if (r < density) g->set_state(x, y, CellState::kUnknown);
    }
  }
  for (int y = 3; y < 15; ++y) g->set_state(12, y, CellState::kOccupied);
  return g;
}

// Brute force over every cell: distance from p to the nearest blocked square or the outside.
double brute_point_distance(const OccupancyGrid& g, const Eigen::Vector2d& p) {
  const auto e = g.extent();
  if (!e.contains(p)) return 0.0;
  double best = std::min({p.x() - e.min().x(), e.max().x() - p.x(), p.y() - e.min().y(), e.max().y() - p.y()});
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (!g.blocked(x, y)) continue;
      const auto b = g.cell_box(x, y);
      best = std::min(best, (p - p.cwiseMax(b.min()).cwiseMin(b.max())).norm());
    }
  }
  return best;
}

bool brute_disc_free(const OccupancyGrid& g, const Eigen::Vector2d& p, double r) {
  const auto e = g.extent();
  if (p.x() - r < e.min().x() || p.x() + r > e.max().x() || p.y() - r < e.min().y() || p.y() + r > e.max().y()) {
    return false;
  }
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (!g.blocked(x, y)) continue;
      const auto b = g.cell_box(x, y);
      if ((p - p.cwiseMax(b.min()).cwiseMin(b.max())).squaredNorm() < r * r) return false;
    }
  }
  return true;
}

BPolygon to_boost(const Polygon& poly) {
  BPolygon out;
  for (const auto& v : poly.vertices) bg::append(out.outer(), BPoint(v.x(), v.y()));
  bg::correct(out);
  return out;
}

BBox to_boost(const Eigen::AlignedBox2d& b) {
  return {BPoint(b.min().x(), b.min().y()), BPoint(b.max().x(), b.max().y())};
}

// Reference for a placed rigid body, with Boost.Geometry for the polygons.
bool brute_shapes_free(const OccupancyGrid& g, const Shapes2d& placed) {
  for (const auto& c : placed.circles) {
    if (!brute_disc_free(g, c.center, c.radius)) return false;
  }
  for (const auto& poly : placed.polygons) {
    for (const auto& v : poly.vertices) {
      if (!g.extent().contains(v)) return false;
    }
    const BPolygon bp = to_boost(poly);
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        if (g.blocked(x, y) && bg::intersects(bp, to_boost(g.cell_box(x, y)))) return false;
      }
    }
  }
  return true;
}

double brute_shapes_distance(const OccupancyGrid& g, const Shapes2d& placed) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : placed.circles) best = std::min(best, brute_point_distance(g, c.center) - c.radius);
  for (const auto& poly : placed.polygons) {
    for (const auto& v : poly.vertices) best = std::min(best, brute_point_distance(g, v));
    const BPolygon bp = to_boost(poly);
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        if (g.blocked(x, y)) best = std::min(best, bg::distance(bp, to_boost(g.cell_box(x, y))));
      }
    }
  }
  return std::max(0.0, best);
}

State state2(double x, double y) {
  State s(2);
  s << x, y;
  return s;
}

TEST(GridEnvironment, DiscCheckerMatchesBruteForce) {
  std::mt19937 gen(7);
  int valid = 0, invalid = 0;
  for (unsigned seed : {1u, 2u, 3u}) {
    auto grid = random_grid(seed);
    for (const double r : {0.02, 0.05, 0.13, 0.37}) {
      const GridEnvironment env(grid, {GridRobot::Kind::kDisc, r, {}});
      core::Counters counters;
      const auto checker = env.make_checker(counters);
      std::uniform_real_distribution<double> ux(-1.1, 2.1), uy(0.4, 2.6);
      for (int i = 0; i < 1500; ++i) {
        const State s = state2(ux(gen), uy(gen));
        const bool expect = brute_disc_free(*grid, {s[0], s[1]}, r);
        ASSERT_EQ(checker->is_valid(s), expect) << "seed " << seed << " r " << r << " at " << s.transpose();
        (expect ? valid : invalid)++;
      }
      EXPECT_EQ(counters.cd_calls(), 1500u);
    }
  }
  EXPECT_GT(valid, 1000);
  EXPECT_GT(invalid, 1000);
}

TEST(GridEnvironment, DiscTouchingASquareIsFree) {
  auto grid = std::make_shared<OccupancyGrid>(10, 10, 1.0);
  grid->set_state(5, 5, CellState::kOccupied);
  const GridEnvironment env(grid, {GridRobot::Kind::kDisc, 0.5, {}});
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  EXPECT_TRUE(checker->is_valid(state2(4.5, 5.5)));     // touches the square's left side
  EXPECT_FALSE(checker->is_valid(state2(4.51, 5.5)));
  EXPECT_TRUE(checker->is_valid(state2(5.5, 6.5)));     // touches the top side
  EXPECT_FALSE(checker->is_valid(state2(6.3, 6.3)));    // corner (6, 6) at 0.42
  EXPECT_TRUE(checker->is_valid(state2(6.4, 6.4)));     // corner at 0.566
  EXPECT_TRUE(checker->is_valid(state2(0.5, 0.5)));     // touches the map's corner
  EXPECT_FALSE(checker->is_valid(state2(0.49, 3.0)));   // pokes out of the map
  EXPECT_FALSE(checker->is_valid(state2(-3.0, 3.0)));   // outside the map
}

TEST(GridEnvironment, DiscClearanceMatchesBruteForce) {
  std::mt19937 gen(11);
  auto grid = random_grid(4);
  const double r = 0.05;
  const GridEnvironment env(grid, {GridRobot::Kind::kDisc, r, {}});
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  std::uniform_real_distribution<double> ux(-1.0, 2.0), uy(0.5, 2.5);
  for (int i = 0; i < 1000; ++i) {
    const State s = state2(ux(gen), uy(gen));
    const Eigen::Vector2d p(s[0], s[1]);
    const double ref = brute_point_distance(*grid, p);
    const Clearance c = checker->clearance(s);
    ASSERT_NEAR(c.distance, std::max(0.0, ref - r), 1e-12) << s.transpose();
    if (ref > 0.0) {
      ASSERT_NEAR((c.obstacle_point.head<2>() - p).norm(), ref, 1e-12);
      ASSERT_NEAR((c.robot_point.head<2>() - p).norm(), r, 1e-12);
    }
  }
  EXPECT_EQ(counters.clearance_calls(), 1000u);
  EXPECT_EQ(counters.cd_calls(), 0u);
}

// The capped distance is min(exact, limit) to the last bit, for limits below, at and beyond the
// distance transform's bound, and 0 inside a blocked cell or outside the map.
TEST(GridObstacles, CappedDistanceIsTheExactDistanceCapped) {
  std::mt19937 gen(12);
  std::uniform_real_distribution<double> ux(-1.2, 2.2), uy(0.3, 2.7);
  int capped = 0, below = 0;
  for (unsigned seed : {5u, 6u}) {
    const auto grid = random_grid(seed, 0.03);
    const GridObstacles obstacles(grid);
    for (int i = 0; i < 400; ++i) {
      const Eigen::Vector2d p(ux(gen), uy(gen));
      const double exact = brute_point_distance(*grid, p);
      for (const double limit : {0.0, 0.01, 0.08, 0.3, 1.0, std::numeric_limits<double>::infinity()}) {
        ASSERT_EQ(obstacles.point_distance_up_to(p, limit), std::min(exact, limit)) << p.transpose() << " " << limit;
        (exact >= limit ? capped : below) += 1;
      }
    }
  }
  EXPECT_GT(capped, 1000);
  EXPECT_GT(below, 1000);
}

// Radii a hair below and above the exact clearance decide the band the distance transform leaves
// open, where only the exact square distances can answer.
TEST(GridEnvironment, DiscDecisionIsExactAtTheClearance) {
  std::mt19937 gen(13);
  for (unsigned seed : {21u, 22u}) {
    auto grid = random_grid(seed, 0.03);
    const GridObstacles obstacles(grid);
    std::uniform_real_distribution<double> ux(-1.0, 2.0), uy(0.5, 2.5);
    int tested = 0;
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector2d p(ux(gen), uy(gen));
      const double d = brute_point_distance(*grid, p);
      if (d < 1e-6) continue;
      ++tested;
      ASSERT_TRUE(obstacles.disc_free(p, d * (1.0 - 1e-9))) << p.transpose() << " d " << d;
      ASSERT_FALSE(obstacles.disc_free(p, d * (1.0 + 1e-9))) << p.transpose() << " d " << d;
    }
    EXPECT_GT(tested, 1500);
  }
}

TEST(GridEnvironment, EmptyMapClearanceIsTheBorder) {
  auto grid = std::make_shared<OccupancyGrid>(8, 4, 0.5, Eigen::Vector2d(1.0, 1.0));
  const GridEnvironment env(grid, {GridRobot::Kind::kDisc, 0.25, {}});
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  const Clearance c = checker->clearance(state2(2.0, 2.2));  // map [1, 5] x [1, 3]
  EXPECT_NEAR(c.distance, 0.8 - 0.25, 1e-12);
  EXPECT_TRUE(c.obstacle_point.isApprox(Eigen::Vector3d(2.0, 3.0, 0.0)));
  EXPECT_TRUE(checker->is_valid(state2(1.25, 2.75)));
}

GridRobot l_shape_robot() {
  GridRobot robot;
  robot.kind = GridRobot::Kind::kRigid;
  Polygon l;
  l.vertices = {{-0.2, -0.1}, {0.25, -0.1}, {0.25, 0.0}, {0.0, 0.0}, {0.0, 0.2}, {-0.2, 0.2}};
  robot.body.polygons.push_back(l);
  Polygon tri;
  tri.vertices = {{0.3, 0.05}, {0.4, 0.05}, {0.3, 0.12}};
  robot.body.polygons.push_back(tri);
  robot.body.circles.push_back({Eigen::Vector2d(-0.25, 0.25), 0.04});
  return robot;
}

TEST(GridEnvironment, RigidCheckerMatchesBoostGeometry) {
  std::mt19937 gen(5);
  auto grid = random_grid(9, 0.015);
  const GridEnvironment env(grid, l_shape_robot());
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  std::uniform_real_distribution<double> ux(-1.1, 2.1), uy(0.4, 2.6), ut(-std::numbers::pi, std::numbers::pi);
  int valid = 0, invalid = 0;
  for (int i = 0; i < 1500; ++i) {
    State s(3);
    s << ux(gen), uy(gen), ut(gen);
    const bool expect = brute_shapes_free(*grid, env.robot_outline(s));
    ASSERT_EQ(checker->is_valid(s), expect) << s.transpose();
    (expect ? valid : invalid)++;
  }
  EXPECT_GT(valid, 100);
  EXPECT_GT(invalid, 100);
  EXPECT_EQ(counters.cd_calls(), 1500u);
}

TEST(GridEnvironment, RigidClearanceMatchesBoostGeometry) {
  std::mt19937 gen(6);
  auto grid = random_grid(10, 0.015);
  const GridEnvironment env(grid, l_shape_robot());
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  std::uniform_real_distribution<double> ux(-1.0, 2.0), uy(0.5, 2.5), ut(-std::numbers::pi, std::numbers::pi);
  int positive = 0;
  for (int i = 0; i < 400; ++i) {
    State s(3);
    s << ux(gen), uy(gen), ut(gen);
    const Shapes2d placed = env.robot_outline(s);
    const double ref = brute_shapes_free(*grid, placed) ? brute_shapes_distance(*grid, placed) : 0.0;
    const Clearance c = checker->clearance(s);
    ASSERT_NEAR(c.distance, ref, 1e-9) << s.transpose();
    if (ref > 0.0) {
      ++positive;
      ASSERT_NEAR((c.robot_point - c.obstacle_point).norm(), ref, 1e-9);
    }
  }
  EXPECT_GT(positive, 50);
}

TEST(GridEnvironment, DescribesItself) {
  auto grid = random_grid(1);
  const GridEnvironment disc(grid, {GridRobot::Kind::kDisc, 0.2, {}});
  EXPECT_EQ(disc.workspace_dimension(), 2);
  EXPECT_EQ(disc.state_dimension(), 2);
  EXPECT_EQ(disc.obstacle_outline().grid, grid.get());
  EXPECT_TRUE(disc.obstacle_outline().shapes.empty());
  EXPECT_DOUBLE_EQ(disc.robot_min_diameter(), 0.4);
  EXPECT_DOUBLE_EQ(disc.robot_radius(), 0.2);
  EXPECT_TRUE(disc.workspace_bounds().max().isApprox(Eigen::Vector3d(2.0, 2.5, 0.0)));
  const Shapes2d o = disc.robot_outline(state2(0.3, 1.0));
  ASSERT_EQ(o.circles.size(), 1u);
  EXPECT_TRUE(o.circles[0].center.isApprox(Eigen::Vector2d(0.3, 1.0)));

  const GridEnvironment rigid(grid, l_shape_robot());
  EXPECT_EQ(rigid.state_dimension(), 3);
  EXPECT_NEAR(rigid.robot_min_diameter(), 0.07 * 0.1 / std::hypot(0.07, 0.1), 1e-12);  // the triangle's height
  EXPECT_NEAR(rigid.robot_radius(), std::hypot(0.4, 0.05), 1e-12);  // the triangle's far corner
  State s(3);
  s << 1.0, 1.0, std::numbers::pi / 2;
  const Shapes2d placed = rigid.robot_outline(s);
  EXPECT_TRUE(placed.polygons[0].vertices[1].isApprox(Eigen::Vector2d(1.1, 1.25)));
  EXPECT_TRUE(rigid.reference_point(s).isApprox(Eigen::Vector3d(1.0, 1.0, 0.0)));

  EXPECT_THROW(GridEnvironment(grid, {GridRobot::Kind::kDisc, 0.0, {}}), ParameterError);
  EXPECT_THROW(GridEnvironment(grid, {GridRobot::Kind::kRigid, 0.0, {}}), ParameterError);
}

}  // namespace
}  // namespace amp::world
