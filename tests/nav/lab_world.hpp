#pragma once
// The policy-search paper's lab as a test map, shared by the nav tests.
#include <memory>

#include "amp/nav/grid_nav_world.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::nav::test {

// 5 cm cells: a 4 x 3.5 m room, a 10 cm wall with a 60 cm door at x 1.7-2.3 (closed when `door` is
// false; `wider` cells wider on each side), and a corridor above it up to y = 5.
inline std::shared_ptr<const GridNavWorld> lab(bool door = true, int wider = 0) {
  auto g = std::make_shared<world::OccupancyGrid>(80, 100, 0.05);
  for (int y = 70; y < 72; ++y) {
    for (int x = 0; x < 80; ++x) {
      if (!door || x < 34 - wider || x >= 46 + wider) g->set_state(x, y, world::CellState::kOccupied);
    }
  }
  return std::make_shared<const GridNavWorld>(g);
}

}  // namespace amp::nav::test
