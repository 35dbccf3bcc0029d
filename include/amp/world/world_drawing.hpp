#pragma once
#include "amp/core/state.hpp"
#include "amp/world/shapes2d.hpp"

namespace amp::world {

class OccupancyGrid;

// What `amp render` draws of a world or a robot: shapes in the plane (3-D worlds: their top view,
// i.e. projection on z = 0), and for map worlds the occupancy grid itself.
struct Outline {
  Shapes2d shapes;
  const OccupancyGrid* grid = nullptr;  // owned by the world; null unless a map world
};

// The role of a world that viz uses: its obstacles and its robot, as drawn.
class WorldDrawing {
 public:
  virtual ~WorldDrawing() = default;
  // Obstacles as drawn by `amp render`.
  virtual Outline obstacle_outline() const = 0;
  // The robot's footprint at state s, world frame (3-D: top view).
  virtual Shapes2d robot_outline(const State& s) const = 0;
};

}  // namespace amp::world
