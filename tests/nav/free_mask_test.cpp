#include "amp/nav/free_mask.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/world/grid_cost_to_go.hpp"
#include "amp/nav/polygon_nav_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

PolygonNavWorld box_world() {
  world::Shapes2d s;
  s.polygons.push_back({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}});
  return PolygonNavWorld(s, Eigen::AlignedBox2d(V(0, 0), V(10, 10)));
}

TEST(FreeMask, PolygonWorldInflatedByTheRadius) {
  const PolygonNavWorld w = box_world();
  // Radius 0.5: discs at cell centres only touch the box and the border, so only the box's 4 cells go.
  EXPECT_EQ(rasterize_free_space(w, 1.0, 0.5).free_count(), 96u);
  // Radius 0.6: the 36 border cells and the 8 cells beside the box's faces go too (the diagonal
  // neighbours' centres are sqrt(0.5) from its corners).
  const FreeMask m = rasterize_free_space(w, 1.0, 0.6);
  EXPECT_EQ(m.width(), 10);
  EXPECT_EQ(m.free_count(), 52u);
  EXPECT_FALSE(m.free(3, 4));
  EXPECT_TRUE(m.free(3, 3));
  EXPECT_EQ(m.cell_of({3.5, 3.5}), m.index(3, 3));
  EXPECT_EQ(m.cell_of({-0.1, 3.5}), -1);
  EXPECT_THROW(rasterize_free_space(w, 0.0, 0.5), ParameterError);
}

TEST(FreeMask, ShortestPathAroundARasterisedBox) {
  // From cell (2, 5) to (7, 5) round the box inflated by 0.6, over the top: up 1, a diagonal to
  // (3, 7), 3 along to (6, 7) (a diagonal at (5, 7) would cut the blocked (5, 6)), a diagonal, down 1.
  world::GridCostToGo sp(rasterize_free_space(box_world(), 1.0, 0.6).cells());
  sp.compute(sp.index(7, 5));
  EXPECT_NEAR(sp.distance(sp.index(2, 5)), 5.0 + 2.0 * std::sqrt(2.0), 1e-12);
}

TEST(FreeMask, MapCellsFollowTheMap) {
  auto g = std::make_shared<world::OccupancyGrid>(6, 4, 0.5, V(-1.0, 2.0));
  g->set_state(2, 1, world::CellState::kOccupied);
  const GridNavWorld w(g);
  const FreeMask m = rasterize_free_space(w, 0.25);
  EXPECT_EQ(m.width(), 6);
  EXPECT_EQ(m.height(), 4);
  EXPECT_TRUE(m.origin().isApprox(V(-1.0, 2.0)));
  // Radius 0.25 = half a cell: every cell but the blocked one is free (touching is free).
  EXPECT_EQ(m.free_count(), 23u);
  EXPECT_FALSE(m.free(2, 1));
  // Radius 0.3: the border ring and the blocked cell's 4 face neighbours go; its diagonal
  // neighbours' centres are sqrt(0.125) > 0.3 from its corners.
  EXPECT_EQ(rasterize_free_space(w, 0.3).free_count(), 4u);
}

}  // namespace
}  // namespace amp::nav
