#include "amp/nav/polygon_nav_world.hpp"

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

world::Polygon square(double x0, double y0, double x1, double y1) { return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}; }

// 10 x 10: a box [4, 6]^2, a circle of radius 1 at (2, 8), a wall from (8, 1) to (8, 3).
PolygonNavWorld hand_world() {
  world::Shapes2d s;
  s.polygons.push_back(square(4, 4, 6, 6));
  s.circles.push_back({{2.0, 8.0}, 1.0});
  s.segments.push_back({{8.0, 1.0}, {8.0, 3.0}});
  return PolygonNavWorld(s, Eigen::AlignedBox2d(V(0, 0), V(10, 10)));
}

TEST(PolygonNavWorld, RaysAgainstTheBox) {
  const PolygonNavWorld w = hand_world();
  EXPECT_DOUBLE_EQ(w.ray_cast({1, 5}, {1, 0}, 100), 3.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({1, 5}, {1, 0}, 2), 2.0);      // clipped at the maximum range
  EXPECT_DOUBLE_EQ(w.ray_cast({1, 4}, {1, 0}, 100), 3.0);    // along the face: touching stops
  EXPECT_NEAR(w.ray_cast({3, 3}, V(1, 1).normalized(), 100), kSqrt2, 1e-12);  // into the corner
  EXPECT_DOUBLE_EQ(w.ray_cast({5, 5}, {1, 0}, 100), 0.0);    // inside
  EXPECT_DOUBLE_EQ(w.ray_cast({6, 5}, {1, 0}, 100), 0.0);    // on the boundary
  EXPECT_DOUBLE_EQ(w.ray_cast({5, 9}, {0, -1}, 100), 3.0);
}

TEST(PolygonNavWorld, RaysAgainstTheCircle) {
  const PolygonNavWorld w = hand_world();
  EXPECT_DOUBLE_EQ(w.ray_cast({2, 5}, {0, 1}, 100), 2.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({5, 8}, {-1, 0}, 100), 2.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({2, 8.5}, {1, 0}, 100), 0.0);  // inside
  EXPECT_DOUBLE_EQ(w.ray_cast({1, 5}, {0, 1}, 100), 3.0);    // tangent at (1, 8)
  // From (5, 8 - 0.6) leftwards: enters at x = 2 + 0.8.
  EXPECT_NEAR(w.ray_cast({5, 7.4}, {-1, 0}, 100), 2.2, 1e-12);
}

TEST(PolygonNavWorld, RaysAgainstTheSegmentWallAndTheBounds) {
  const PolygonNavWorld w = hand_world();
  EXPECT_DOUBLE_EQ(w.ray_cast({6.5, 2}, {1, 0}, 100), 1.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({9, 2}, {-1, 0}, 100), 1.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({8, 0.5}, {0, 1}, 100), 0.5);  // along the wall: its end
  EXPECT_DOUBLE_EQ(w.ray_cast({7, 3}, {1, 0}, 100), 1.0);    // grazing its end point
  EXPECT_DOUBLE_EQ(w.ray_cast({7, 3.5}, {1, 0}, 100), 3.0);  // past it: the border
  EXPECT_DOUBLE_EQ(w.ray_cast({7, 2}, {0, -1}, 100), 2.0);
  EXPECT_DOUBLE_EQ(w.ray_cast({0, 2}, {1, 0}, 100), 0.0);    // on the border
  EXPECT_DOUBLE_EQ(w.ray_cast({-1, 2}, {1, 0}, 100), 0.0);   // outside
}

TEST(PolygonNavWorld, NearestObstacleAndClearance) {
  const PolygonNavWorld w = hand_world();
  NearestObstacle n = w.nearest_obstacle({3, 5});
  EXPECT_DOUBLE_EQ(n.distance, 1.0);
  EXPECT_TRUE(n.point.isApprox(V(4, 5)));
  n = w.nearest_obstacle({2, 6});
  EXPECT_DOUBLE_EQ(n.distance, 1.0);
  EXPECT_TRUE(n.point.isApprox(V(2, 7)));
  n = w.nearest_obstacle({7, 2});
  EXPECT_DOUBLE_EQ(n.distance, 1.0);
  EXPECT_TRUE(n.point.isApprox(V(8, 2)));
  n = w.nearest_obstacle({0.5, 5});
  EXPECT_DOUBLE_EQ(n.distance, 0.5);
  EXPECT_TRUE(n.point.isApprox(V(0, 5)));
  n = w.nearest_obstacle({3, 3});
  EXPECT_NEAR(n.distance, kSqrt2, 1e-12);
  EXPECT_TRUE(n.point.isApprox(V(4, 4)));
  EXPECT_EQ(w.nearest_obstacle({5, 5}).distance, 0.0);
  EXPECT_DOUBLE_EQ(w.clearance({3, 5}, 0.25), 0.75);
}

TEST(PolygonNavWorld, DiscFreeTouchingIsFree) {
  const PolygonNavWorld w = hand_world();
  EXPECT_TRUE(w.disc_free({3, 5}, 1.0));
  EXPECT_FALSE(w.disc_free({3, 5}, 1.01));
  EXPECT_FALSE(w.disc_free({5, 5}, 0.1));    // inside the box, far from its edges
  EXPECT_FALSE(w.disc_free({0.5, 5}, 0.6));  // leaves the bounds
  EXPECT_FALSE(w.disc_free({7.5, 2}, 0.6));  // the wall
  EXPECT_TRUE(w.disc_free({7.5, 2}, 0.5));
  EXPECT_FALSE(w.disc_free({2, 6.5}, 0.6));  // the circle
}

// Brute force over every shape: the exact first hit.
double brute_ray(const world::Shapes2d& s, const Eigen::AlignedBox2d& b, const V& p, const V& d, double max_range) {
  const PolygonNavWorld one_at_a_time(world::Shapes2d{}, b);
  double best = one_at_a_time.ray_cast(p, d, max_range);
  for (const auto& poly : s.polygons) {
    const PolygonNavWorld w(world::Shapes2d{{poly}, {}}, b);
    best = std::min(best, w.ray_cast(p, d, max_range));
  }
  for (const auto& c : s.circles) {
    const PolygonNavWorld w(world::Shapes2d{{}, {c}}, b);
    best = std::min(best, w.ray_cast(p, d, max_range));
  }
  return best;
}

TEST(PolygonNavWorld, BroadPhaseRaysEqualOneShapeAtATime) {
  core::Rng rng(7);
  world::Shapes2d s;
  for (int i = 0; i < 40; ++i) {
    const V c(rng.uniform(1, 19), rng.uniform(1, 19));
    if (i % 2 == 0) {
      s.circles.push_back({c, rng.uniform(0.1, 0.6)});
    } else {
      const double h = rng.uniform(0.1, 0.6);
      s.polygons.push_back({{c + V(-h, -h), c + V(h, -0.5 * h), c + V(0.2 * h, h)}});
    }
  }
  const Eigen::AlignedBox2d b(V(0, 0), V(20, 20));
  const PolygonNavWorld w(s, b);
  for (int i = 0; i < 300; ++i) {
    const V p(rng.uniform(0, 20), rng.uniform(0, 20));
    const double a = rng.uniform(0, 2 * M_PI);
    const V d(std::cos(a), std::sin(a));
    EXPECT_NEAR(w.ray_cast(p, d, 15.0), brute_ray(s, b, p, d, 15.0), 1e-9) << i;
  }
}

TEST(PolygonNavWorld, ChangesAddAndRemoveShapes) {
  const PolygonNavWorld w = hand_world();
  ObstacleChange add;
  add.shapes.circles.push_back({{2.0, 5.0}, 0.5});
  const auto added = w.changed(add);
  EXPECT_DOUBLE_EQ(added->ray_cast({1, 5}, {1, 0}, 100), 0.5);
  EXPECT_DOUBLE_EQ(w.ray_cast({1, 5}, {1, 0}, 100), 3.0);  // the original is unchanged
  ObstacleChange remove;
  remove.action = ObstacleChange::Action::kVanish;
  remove.shapes.polygons.push_back(square(4, 4, 6, 6));
  const auto removed = added->changed(remove);
  EXPECT_DOUBLE_EQ(removed->ray_cast({3, 5}, {1, 0}, 100), 7.0);
  EXPECT_THROW(removed->changed(remove), ParameterError);  // no longer there
  ObstacleChange cells;
  cells.cells.push_back({0, 0, 1, 1});
  EXPECT_THROW(w.changed(cells), ParameterError);
}

}  // namespace
}  // namespace amp::nav
