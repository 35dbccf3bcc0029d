// merge_tiles and drop_segments_on_polygon_edges: hand-made cases, then the checker's answers on
// random states, which must not change when a world or a robot is merged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "amp/core/rng.hpp"
#include "amp/world/outline_merge.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

Polygon tri(V a, V b, V c) { return Polygon{{a, b, c}}; }

// The vertices as a set, for comparing outlines whatever vertex they start at.
std::vector<std::pair<double, double>> vertex_set(const Polygon& p) {
  std::vector<std::pair<double, double>> v;
  for (const V& q : p.vertices) v.emplace_back(q.x(), q.y());
  std::sort(v.begin(), v.end());
  return v;
}

TEST(MergeTiles, TwoTrianglesOfASquareAndTheirCopiesBecomeTheSquare) {
  const V a(0, 0), b(2, 0), c(2, 1), d(0, 1);
  // A clockwise copy and a rotated copy, as a prism's top and bottom caps give them.
  const std::vector<Polygon> out = merge_tiles({tri(a, b, c), tri(a, c, d), tri(c, b, a), tri(d, a, c)});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(vertex_set(out[0]), vertex_set(Polygon{{a, b, c, d}}));
  EXPECT_DOUBLE_EQ(signed_area(out[0].vertices), 2.0);  // counter-clockwise
}

TEST(MergeTiles, AFanBecomesItsHexagonWithoutTheCentre) {
  std::vector<Polygon> fan;
  std::vector<V> ring;
  for (int i = 0; i < 6; ++i) ring.push_back(V(std::cos(i * kPi / 3), std::sin(i * kPi / 3)));
  for (int i = 0; i < 6; ++i) fan.push_back(tri(V(0, 0), ring[i], ring[(i + 1) % 6]));
  const std::vector<Polygon> out = merge_tiles(fan);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(vertex_set(out[0]), vertex_set(Polygon{ring}));
}

TEST(MergeTiles, CollinearVerticesOfTheOutlineAreDropped) {
  // Two squares side by side: the shared side's ends lie on the rectangle's long sides.
  const std::vector<Polygon> out =
      merge_tiles({tri({0, 0}, {1, 0}, {1, 1}), tri({0, 0}, {1, 1}, {0, 1}), tri({1, 0}, {2, 0}, {2, 1}),
                   tri({1, 0}, {2, 1}, {1, 1})});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].vertices.size(), 4u);
}

TEST(MergeTiles, ARingKeepsItsPieces) {
  // A square frame around a hole: its outline is two loops.
  const V o[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}}, i[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Polygon> ring;
  for (int k = 0; k < 4; ++k) {
    ring.push_back(tri(o[k], o[(k + 1) % 4], i[(k + 1) % 4]));
    ring.push_back(tri(o[k], i[(k + 1) % 4], i[k]));
  }
  EXPECT_EQ(merge_tiles(ring).size(), 8u);
}

TEST(MergeTiles, OverlappingAndPinchedPiecesAreKept) {
  // Two triangles that overlap along a shared directed edge.
  EXPECT_EQ(merge_tiles({tri({0, 0}, {2, 0}, {1, 1}), tri({0, 0}, {2, 0}, {1, 2})}).size(), 2u);
  // Four triangles meeting two by two at one vertex: two loops through (1, 1).
  const std::vector<Polygon> bow = {tri({0, 0}, {1, 0}, {1, 1}), tri({0, 0}, {1, 1}, {0, 1}),
                                    tri({1, 1}, {2, 1}, {2, 2}), tri({1, 1}, {2, 2}, {1, 2})};
  EXPECT_EQ(merge_tiles(bow).size(), 2u);  // each square merges on its own: they share no edge
  // A T-junction: the small square's side is half of the big one's, so no edge is shared.
  const std::vector<Polygon> t = {tri({0, 0}, {2, 0}, {2, 2}), tri({0, 0}, {2, 2}, {0, 2}),
                                  tri({0, 2}, {1, 2}, {1, 3}), tri({0, 2}, {1, 3}, {0, 3})};
  EXPECT_EQ(merge_tiles(t).size(), 2u);
}

TEST(DropSegments, SegmentsOnPolygonEdgesGoOthersStay) {
  Shapes2d s;
  s.polygons = {Polygon{{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}}};  // (2, 0) splits the bottom edge
  s.segments = {{{0, 0}, {4, 0}},    // along two collinear edges: covered
                {{1, 0}, {3, 0}},    // inside the bottom side: covered
                {{4, 2}, {4, 0}},    // a side, reversed: covered
                {{3, 0}, {5, 0}},    // half off the polygon: kept
                {{1, 1}, {3, 1}},    // inside, not on an edge: kept
                {{0, 3}, {4, 3}}};   // elsewhere: kept
  drop_segments_on_polygon_edges(s);
  ASSERT_EQ(s.segments.size(), 3u);
  EXPECT_EQ(s.segments[0].a, V(3, 0));
  EXPECT_EQ(s.segments[1].a, V(1, 1));
  EXPECT_EQ(s.segments[2].a, V(0, 3));
}

// Star-shaped polygons cut into fans around their centre, with copies, reversed pieces, unit-square
// tiles (rings and pinches among them) and wall segments along and across their edges.
Shapes2d random_pieces(core::Rng& rng) {
  Shapes2d s;
  for (int k = 0; k < 12; ++k) {
    const V c(rng.uniform(0, 20), rng.uniform(0, 20));
    const int n = 3 + static_cast<int>(rng.uniform_index(8));
    std::vector<double> angle(n);
    for (double& a : angle) a = rng.uniform(0, 2 * kPi);
    std::sort(angle.begin(), angle.end());
    std::vector<V> ring;
    for (double a : angle) ring.push_back(c + rng.uniform(0.5, 2.5) * V(std::cos(a), std::sin(a)));
    if (!is_simple(ring) || signed_area(ring) <= 0.1) continue;
    for (int i = 0; i < n; ++i) {
      const Polygon t = tri(c, ring[i], ring[(i + 1) % n]);
      if (signed_area(t.vertices) <= 1e-6) continue;
      s.polygons.push_back(t);
      if (rng.uniform(0, 1) < 0.3) s.polygons.push_back(tri(ring[(i + 1) % n], ring[i], c));
      if (rng.uniform(0, 1) < 0.3) s.segments.push_back({ring[i], ring[(i + 1) % n]});
    }
  }
  for (int x = 0; x < 20; x += 2) {
    for (int y = 0; y < 20; y += 2) {
      if (rng.uniform(0, 1) < 0.7) continue;
      const V a(x, y), b(x + 2, y), c(x + 2, y + 2), d(x, y + 2);
      s.polygons.push_back(tri(a, b, c));
      s.polygons.push_back(tri(a, c, d));
      s.segments.push_back({a, b});
    }
  }
  for (int k = 0; k < 10; ++k) {
    s.segments.push_back({V(rng.uniform(0, 20), rng.uniform(0, 20)), V(rng.uniform(0, 20), rng.uniform(0, 20))});
  }
  return s;
}

TEST(OutlineMerge, CheckerAnswersAreUnchangedOnRandomWorldsAndRobots) {
  core::Rng rng(11);
  const Eigen::AlignedBox2d bounds(V(-3, -3), V(23, 23));
  for (int w = 0; w < 6; ++w) {
    const Shapes2d pieces = random_pieces(rng);
    Shapes2d merged = pieces;
    merged.polygons = merge_tiles(merged.polygons);
    drop_segments_on_polygon_edges(merged);
    ASSERT_LT(merged.polygons.size(), pieces.polygons.size());
    ASSERT_LT(merged.segments.size(), pieces.segments.size());
    // The robot: a fan of an L's two rectangles, with copies, against its merged outline.
    const std::vector<Polygon> robot_pieces = {
        tri({-1, -0.2}, {1, -0.2}, {1, 0.2}),   tri({-1, -0.2}, {1, 0.2}, {-0.6, 0.2}),
        tri({-1, -0.2}, {-0.6, 0.2}, {-1, 0.2}), tri({-1, 0.2}, {-0.6, 0.2}, {-0.6, 1}),
        tri({-1, 0.2}, {-0.6, 1}, {-1, 1}),      tri({1, 0.2}, {-1, -0.2}, {1, -0.2})};
    const std::vector<Polygon> robot_merged = merge_tiles(robot_pieces);
    ASSERT_EQ(robot_merged.size(), 1u);
    core::Counters counters;
    const auto world_a = std::make_shared<const PlanarWorld>(pieces, bounds);
    const auto world_b = std::make_shared<const PlanarWorld>(merged, bounds);
    const PlanarChecker a(world_a, PlanarRobot::rigid({robot_pieces, {}}), counters);
    const PlanarChecker b(world_b, PlanarRobot::rigid({robot_merged, {}}), counters);
    int valid = 0;
    for (int i = 0; i < 2000; ++i) {
      State s(3);
      s << rng.uniform(-2, 22), rng.uniform(-2, 22), rng.uniform(-kPi, kPi);
      const bool va = a.is_valid(s);
      ASSERT_EQ(va, b.is_valid(s)) << "world " << w << " state " << s.transpose();
      if (!va) continue;
      ++valid;
      EXPECT_NEAR(a.clearance(s).distance, b.clearance(s).distance, 1e-12) << s.transpose();
    }
    EXPECT_GT(valid, 100);
    EXPECT_LT(valid, 1900);
  }
}

}  // namespace
}  // namespace amp::world
