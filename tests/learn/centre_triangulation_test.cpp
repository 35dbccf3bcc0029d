#include "amp/learn/centre_triangulation.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

using Edge = std::pair<int, int>;

// Brute-force Delaunay edges of points in general position: the edges of every triangle whose
// circumcircle holds no other point (O(n^4), for small n).
std::vector<Edge> brute_force_edges(const std::vector<std::pair<int, Eigen::Vector2d>>& pts) {
  std::set<Edge> out;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        const Eigen::Vector2d a = pts[i].second, b = pts[j].second, c = pts[k].second;
        const double orient = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (std::abs(orient) < 1e-12) continue;
        bool empty = true;
        for (std::size_t m = 0; m < n && empty; ++m) {
          if (m == i || m == j || m == k) continue;
          const Eigen::Vector2d d = pts[m].second;
          // In-circle determinant, sign-corrected by the orientation of (a, b, c).
          const double ax = a.x() - d.x(), ay = a.y() - d.y(), bx = b.x() - d.x(), by = b.y() - d.y(),
                       cx = c.x() - d.x(), cy = c.y() - d.y();
          const double det = (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay) +
                             (cx * cx + cy * cy) * (ax * by - bx * ay);
          if (det * orient > 0) empty = false;
        }
        if (!empty) continue;
        for (auto [u, v] : {Edge{i, j}, Edge{j, k}, Edge{i, k}}) {
          const int x = pts[u].first, y = pts[v].first;
          out.emplace(std::min(x, y), std::max(x, y));
        }
      }
    }
  }
  return {out.begin(), out.end()};
}

TEST(CentreTriangulation, SquareWithCentre) {
  // Unit square corners 0..3 and its centre 4: the centre joins all four corners, plus the four sides.
  CentreTriangulation t;
  t.insert(0, {0, 0});
  t.insert(1, {1, 0});
  t.insert(2, {1, 1});
  t.insert(3, {0, 1});
  t.insert(4, {0.5, 0.5});
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
  std::vector<int> nb;
  t.neighbours(4, nb);
  EXPECT_EQ(nb, (std::vector<int>{0, 1, 2, 3}));
  t.neighbours(0, nb);
  EXPECT_EQ(nb, (std::vector<int>{1, 3, 4}));
  EXPECT_EQ(t.nearest({0.9, 0.1}), 1);
  EXPECT_EQ(t.nearest({0.45, 0.55}), 4);
}

TEST(CentreTriangulation, MatchesBruteForceAfterInsertsMovesAndRemovals) {
  core::Rng rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    CentreTriangulation t;
    std::vector<Eigen::Vector2d> pos(60);
    std::vector<char> alive(60, 0);
    for (int op = 0; op < 300; ++op) {
      const int id = static_cast<int>(rng.uniform_index(60));
      const Eigen::Vector2d p(rng.uniform01(), rng.uniform01());
      if (!alive[id]) {
        t.insert(id, p);
        alive[id] = 1;
      } else if (rng.uniform01() < 0.7) {
        // Mostly small moves, as a learning centre makes, and a few jumps.
        const Eigen::Vector2d to = rng.uniform01() < 0.8 ? Eigen::Vector2d(pos[id] + 0.05 * (p - pos[id])) : p;
        t.move(id, to);
        pos[id] = to;
        continue;
      } else {
        t.remove(id);
        alive[id] = 0;
        continue;
      }
      pos[id] = p;
    }
    std::vector<std::pair<int, Eigen::Vector2d>> pts;
    for (int i = 0; i < 60; ++i) {
      if (alive[i]) pts.emplace_back(i, pos[i]);
    }
    ASSERT_GE(pts.size(), 10u);
    EXPECT_EQ(t.size(), static_cast<int>(pts.size()));
    EXPECT_EQ(t.edges(), brute_force_edges(pts)) << "trial " << trial;
    // nearest() is the brute-force nearest centre.
    for (int q = 0; q < 50; ++q) {
      const Eigen::Vector2d x(rng.uniform01(), rng.uniform01());
      const auto best = std::min_element(pts.begin(), pts.end(), [&](const auto& a, const auto& b) {
        return (a.second - x).squaredNorm() < (b.second - x).squaredNorm();
      });
      EXPECT_EQ(t.nearest(x), best->first);
    }
  }
}

TEST(CentreTriangulation, DuplicatesAreHiddenUntilTheyMoveApart) {
  CentreTriangulation t;
  t.insert(0, {0, 0});
  t.insert(1, {1, 0});
  t.insert(2, {0, 1});
  t.insert(3, {0, 0});  // on top of 0
  EXPECT_TRUE(t.hidden(3));
  EXPECT_EQ(t.size(), 4);
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  std::vector<int> nb;
  t.neighbours(3, nb);
  EXPECT_TRUE(nb.empty());
  EXPECT_EQ(t.nearest({0.01, 0.01}), 0);
  t.move(3, {0.4, 0.4});  // moves apart: triangulated
  EXPECT_FALSE(t.hidden(3));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
  t.move(0, {0.4, 0.4});  // onto 3: 0 is hidden
  EXPECT_TRUE(t.hidden(0));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{1, 2}, {1, 3}, {2, 3}}));
  t.remove(3);  // 0 takes 3's place
  EXPECT_FALSE(t.hidden(0));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  t.move(1, {0.4, 0.4});  // onto 0, then 0 moves away: 1 is revealed
  EXPECT_TRUE(t.hidden(1));
  t.move(0, {0, 0});
  EXPECT_FALSE(t.hidden(1));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}}));
  t.remove(1);
  t.remove(0);
  t.remove(2);
  EXPECT_EQ(t.size(), 0);
  EXPECT_EQ(t.nearest({0, 0}), -1);
}

TEST(CentreTriangulation, CollinearCentresFormAPath) {
  CentreTriangulation t;
  t.insert(2, {2, 2});
  t.insert(0, {0, 0});
  t.insert(1, {1, 1});
  t.insert(3, {3, 3});
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}}));
  std::vector<int> nb;
  t.neighbours(1, nb);
  EXPECT_EQ(nb, (std::vector<int>{0, 2}));
  t.neighbours(3, nb);
  EXPECT_EQ(nb, (std::vector<int>{2}));
  t.insert(4, {1, 1});  // a duplicate on the line
  EXPECT_TRUE(t.hidden(4));
  t.move(4, {1, 0});  // off the line: now 2-dimensional
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
  t.remove(4);
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}}));
  // A single centre, and two.
  CentreTriangulation s;
  s.insert(5, {0, 0});
  s.neighbours(5, nb);
  EXPECT_TRUE(nb.empty());
  EXPECT_TRUE(s.edges().empty());
  s.insert(6, {0, 0});
  s.insert(7, {1, 0});
  EXPECT_EQ(s.edges(), (std::vector<Edge>{{5, 7}}));
}

TEST(CentreTriangulation, BadIdsThrow) {
  CentreTriangulation t;
  EXPECT_THROW(t.insert(-1, {0, 0}), std::invalid_argument);
  t.insert(0, {0, 0});
  EXPECT_THROW(t.insert(0, {1, 0}), std::invalid_argument);
  EXPECT_THROW(t.move(3, {1, 0}), std::invalid_argument);
  EXPECT_THROW(t.remove(9), std::invalid_argument);
}

}  // namespace
}  // namespace amp::learn
