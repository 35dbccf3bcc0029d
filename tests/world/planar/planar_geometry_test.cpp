#include <gtest/gtest.h>

#include <cmath>

#include "amp/core/error.hpp"
#include "amp/world/planar_world.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;

std::vector<V> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(PolygonGeometry, SegmentsCrossTouchAndMiss) {
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));   // proper crossing
  EXPECT_TRUE(segments_intersect({0, 0}, {1, 0}, {1, 0}, {2, 5}));   // shared endpoint
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {1, 3}));   // T junction
  EXPECT_TRUE(segments_intersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));   // collinear overlap
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));  // collinear, apart
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 1}, {0, 1}, {0.4, 0.6 + 1e-9}));
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));  // parallel
}

TEST(PolygonGeometry, PointSegmentAndSegmentSegmentDistances) {
  V q;
  EXPECT_DOUBLE_EQ(point_segment_distance_sq({0.5, 2}, {0, 0}, {1, 0}, &q), 4.0);
  EXPECT_EQ(q, V(0.5, 0));
  EXPECT_DOUBLE_EQ(point_segment_distance_sq({3, 4}, {0, 0}, {0, 0}), 25.0);  // degenerate segment
  EXPECT_DOUBLE_EQ(point_segment_distance_sq({-3, 4}, {0, 0}, {1, 0}, &q), 25.0);
  EXPECT_EQ(q, V(0, 0));
  V p1, p2;
  EXPECT_DOUBLE_EQ(segment_segment_distance_sq({0, 0}, {1, 0}, {2, 1}, {3, 1}, &p1, &p2), 2.0);
  EXPECT_EQ(p1, V(1, 0));
  EXPECT_EQ(p2, V(2, 1));
  EXPECT_DOUBLE_EQ(segment_segment_distance_sq({0, 0}, {2, 2}, {0, 2}, {2, 0}, &p1, &p2), 0.0);
  EXPECT_NEAR((p1 - V(1, 1)).norm(), 0.0, 1e-15);
}

TEST(PolygonGeometry, AreaOrientationConvexitySimplicity) {
  const auto sq = square(0, 0, 2);
  EXPECT_DOUBLE_EQ(signed_area(sq), 4.0);
  const std::vector<V> cw(sq.rbegin(), sq.rend());
  EXPECT_DOUBLE_EQ(signed_area(cw), -4.0);
  EXPECT_TRUE(is_convex(sq));
  EXPECT_TRUE(is_convex(cw));
  const std::vector<V> u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_FALSE(is_convex(u));
  EXPECT_TRUE(is_simple(u));
  EXPECT_DOUBLE_EQ(signed_area(u), 7.0);
  const std::vector<V> bow = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  int i = -1, j = -1;
  EXPECT_FALSE(is_simple(bow, &i, &j));
  EXPECT_EQ(i, 0);
  EXPECT_EQ(j, 2);
  const auto box = bounding_box(u);
  EXPECT_EQ(box.min(), V(0, 0));
  EXPECT_EQ(box.max(), V(3, 3));
}

TEST(PolygonGeometry, PointInNonConvexPolygon) {
  const std::vector<V> u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_TRUE(point_in_polygon({0.5, 2.5}, u));
  EXPECT_TRUE(point_in_polygon({2.5, 2.5}, u));
  EXPECT_TRUE(point_in_polygon({1.5, 0.5}, u));
  EXPECT_FALSE(point_in_polygon({1.5, 2.0}, u));  // in the notch
  EXPECT_FALSE(point_in_polygon({4, 1}, u));
}

TEST(PolygonGeometry, OverlapPredicatesAreClosed) {
  const auto a = square(0, 0, 1);
  EXPECT_TRUE(polygons_overlap(a, square(1, 0, 1)));          // shared edge
  EXPECT_TRUE(polygons_overlap(a, square(1, 1, 1)));          // shared corner
  EXPECT_FALSE(polygons_overlap(a, square(1 + 1e-12, 0, 1)));
  EXPECT_TRUE(polygons_overlap(a, square(0.25, 0.25, 0.5)));  // b inside a
  EXPECT_TRUE(polygons_overlap(square(0.25, 0.25, 0.5), a));  // a inside b
  EXPECT_TRUE(polygon_circle_overlap(a, {2, 0.5}, 1.0));      // tangent
  EXPECT_FALSE(polygon_circle_overlap(a, {2, 0.5}, 0.999));
  EXPECT_TRUE(polygon_circle_overlap(a, {0.5, 0.5}, 0.1));    // disc inside
  EXPECT_TRUE(polygon_circle_overlap(a, {0.5, 0.5}, 10.0));   // polygon inside disc
}

TEST(PolygonGeometry, HullAndMinimumWidth) {
  std::vector<V> pts = square(0, 0, 1);
  pts.push_back({0.5, 0.5});
  pts.push_back({1, 0.5});  // collinear on the hull: dropped
  EXPECT_EQ(convex_hull(pts).size(), 4u);
  EXPECT_DOUBLE_EQ(minimum_width({{0, 0}, {4, 0}, {4, 1}, {0, 1}}), 1.0);
  // Equilateral triangle of side 2: width = its height sqrt(3).
  EXPECT_NEAR(minimum_width({{0, 0}, {2, 0}, {1, std::sqrt(3.0)}}), std::sqrt(3.0), 1e-12);
}

TEST(PlanarWorld, RejectsInvalidShapesAndBounds) {
  const Eigen::AlignedBox2d b(V(0, 0), V(10, 10));
  auto world_with = [&](Shapes2d s) { return PlanarWorld(std::move(s), b); };
  EXPECT_THROW(world_with({{Polygon{{{0, 0}, {1, 0}}}}, {}}), ParameterError);                   // 2 vertices
  EXPECT_THROW(world_with({{Polygon{{{0, 0}, {1, 1}, {2, 2}}}}, {}}), ParameterError);           // zero area
  EXPECT_THROW(world_with({{Polygon{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}}, {}}), ParameterError);   // bow tie
  EXPECT_THROW(world_with({{Polygon{{{0, 0}, {NAN, 0}, {1, 1}}}}, {}}), ParameterError);         // NaN
  EXPECT_THROW(world_with({{}, {Circle{{1, 1}, 0.0}}}), ParameterError);
  EXPECT_THROW(world_with({{}, {Circle{{1, 1}, -1.0}}}), ParameterError);
  EXPECT_THROW(PlanarWorld({}, Eigen::AlignedBox2d(V(0, 0), V(0, 1))), ParameterError);
  try {
    world_with({{Polygon{square(0, 0, 1)}, Polygon{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}}, {}});
    FAIL() << "expected a ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("obstacle polygon 1"), std::string::npos) << e.what();
  }
  const PlanarWorld ok({{Polygon{square(1, 1, 2)}}, {Circle{{5, 5}, 1}}}, b);
  EXPECT_EQ(ok.edges().size(), 4u);
  EXPECT_EQ(ok.obstacles().circles.size(), 1u);
  EXPECT_FALSE(ok.grid().empty());
}

TEST(PlanarWorld, GridParityTestMatchesPointInPolygon) {
  // A comb-shaped non-convex polygon spanning many grid cells.
  std::vector<V> comb = {{0, 0}, {9, 0}};  // bar [0,9]x[0,2] with teeth [2j,2j+1]x[2,10]
  for (int j = 4; j >= 0; --j) {
    comb.push_back({2.0 * j + 1, 10});
    comb.push_back({2.0 * j, 10});
    if (j > 0) {
      comb.push_back({2.0 * j, 2});
      comb.push_back({2.0 * j - 1, 2});
    }
  }
  ASSERT_TRUE(is_simple(comb));
  const PlanarWorld w({{Polygon{comb}}, {}}, Eigen::AlignedBox2d(V(-1, -1), V(11, 11)));
  std::vector<int> scratch;
  scratch.reserve(w.grid().max_parity_items());
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 20000; ++i) {
    const V p(-1 + 12 * next(), -1 + 12 * next());
    EXPECT_EQ(w.point_in_obstacle_polygon(p, scratch), point_in_polygon(p, comb)) << p.transpose();
  }
}

}  // namespace
}  // namespace amp::world
