#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/world/distance_transform.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::world {
namespace {

// Brute force: squared centre distance to every site.
std::vector<double> brute_force(int w, int h, const std::vector<std::uint8_t>& site) {
  std::vector<double> d(site.size(), DistanceTransform::kNoSite);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int sy = 0; sy < h; ++sy) {
        for (int sx = 0; sx < w; ++sx) {
          if (!site[sy * w + sx]) continue;
          const double dd = double(x - sx) * (x - sx) + double(y - sy) * (y - sy);
          if (dd < d[y * w + x]) d[y * w + x] = dd;
        }
      }
    }
  }
  return d;
}

void expect_matches_brute_force(int w, int h, const std::vector<std::uint8_t>& site) {
  const DistanceTransform dt(w, h, site);
  const std::vector<double> ref = brute_force(w, h, site);
  for (int i = 0; i < w * h; ++i) {
    ASSERT_EQ(dt.squared_distance(i), ref[i]) << "cell " << i << " of " << w << "x" << h;
    const std::int32_t n = dt.nearest(i);
    if (ref[i] == DistanceTransform::kNoSite) {
      ASSERT_EQ(n, -1);
      continue;
    }
    ASSERT_GE(n, 0);
    ASSERT_TRUE(site[n]) << "nearest of cell " << i << " is not a site";
    const double dx = i % w - n % w, dy = i / w - n / w;
    ASSERT_EQ(dx * dx + dy * dy, ref[i]) << "nearest of cell " << i << " is not at the distance";
  }
}

TEST(GridDistanceTransform, MatchesBruteForceOnRandomGrids) {
  std::mt19937 gen(12345);
  const int sizes[][2] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {13, 9}, {31, 40}, {64, 17}, {50, 50}};
  for (const auto& s : sizes) {
    for (const double density : {0.002, 0.02, 0.1, 0.5, 0.95}) {
      for (int trial = 0; trial < 3; ++trial) {
        std::bernoulli_distribution occ(density);
        std::vector<std::uint8_t> site(static_cast<std::size_t>(s[0] * s[1]));
        for (auto& c : site) c = occ(gen) ? 1 : 0;
        SCOPED_TRACE(std::to_string(s[0]) + "x" + std::to_string(s[1]) + " density " + std::to_string(density));
        expect_matches_brute_force(s[0], s[1], site);
      }
    }
  }
}

TEST(GridDistanceTransform, SingleSiteAndFarCorners) {
  std::vector<std::uint8_t> site(20 * 10, 0);
  site[3 * 20 + 17] = 1;  // (17, 3)
  const DistanceTransform dt(20, 10, site);
  EXPECT_EQ(dt.squared_distance(0), 17.0 * 17 + 9);
  EXPECT_EQ(dt.squared_distance(9 * 20 + 0), 17.0 * 17 + 36);
  EXPECT_EQ(dt.nearest(9 * 20 + 0), 3 * 20 + 17);
  EXPECT_EQ(dt.squared_distance(3 * 20 + 17), 0.0);
}

TEST(GridDistanceTransform, EmptyAndFullGrids) {
  const DistanceTransform empty(7, 5, std::vector<std::uint8_t>(35, 0));
  for (int i = 0; i < 35; ++i) {
    EXPECT_EQ(empty.squared_distance(i), DistanceTransform::kNoSite);
    EXPECT_EQ(empty.nearest(i), -1);
  }
  const DistanceTransform full(7, 5, std::vector<std::uint8_t>(35, 1));
  for (int i = 0; i < 35; ++i) {
    EXPECT_EQ(full.squared_distance(i), 0.0);
    EXPECT_EQ(full.nearest(i), i);
  }
}

TEST(GridDistanceTransform, GridSitesAreBlockedCells) {
  OccupancyGrid g(4, 3, 0.1);
  g.set_state(0, 0, CellState::kOccupied);
  g.set_state(3, 2, CellState::kUnknown);  // unknown counts as an obstacle
  const DistanceTransform dt(g);
  EXPECT_EQ(dt.squared_distance(g.index(3, 1)), 1.0);
  EXPECT_EQ(dt.nearest(g.index(3, 1)), static_cast<std::int32_t>(g.index(3, 2)));
  EXPECT_EQ(dt.squared_distance(g.index(1, 1)), 2.0);
  EXPECT_EQ(dt.nearest(g.index(1, 1)), static_cast<std::int32_t>(g.index(0, 0)));
}

TEST(GridDistanceTransform, RejectsMismatchedRaster) {
  DistanceTransform dt;
  EXPECT_THROW(dt.compute(3, 3, std::vector<std::uint8_t>(8, 0)), ParameterError);
  EXPECT_THROW(dt.compute(0, 3, {}), ParameterError);
}

}  // namespace
}  // namespace amp::world
