#pragma once
#include <cstddef>
#include <vector>

#include "amp/world/shapes2d.hpp"

namespace amp::nav {

// An inclusive rectangle of map cells, (x0, y0) to (x1, y1).
struct CellRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Obstacles that appear or vanish. On a polygon world `shapes` are added (appear) or removed
// (vanish: each must equal an obstacle present at that time, polygon vertices or circle centre and
// radius within 1e-9). On a map, `cells` are set occupied (appear) or free (vanish), and `shapes`
// act on every cell whose square they overlap with positive area. Segment walls cannot change.
struct ObstacleChange {
  enum class Action { kAppear, kVanish };
  Action action = Action::kAppear;
  world::Shapes2d shapes;
  std::vector<CellRect> cells;
};

// A change that takes effect at the start of step `step` (steps count from 0; step 0 changes the
// world before the first move).
struct WorldEvent {
  std::size_t step = 0;
  ObstacleChange change;
};

}  // namespace amp::nav
