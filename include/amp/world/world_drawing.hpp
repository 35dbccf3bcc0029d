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
  // A second, front view of a 3-D world (orthographic, seen along +y: x to the right, z up), beside
  // the top view, so that heights read: an arm above a table, a shelf's boards. 2-D worlds have none.
  virtual bool has_front_view() const { return false; }
  // The obstacles and the robot as the front view draws them, in its (x, z) coordinates.
  virtual Outline obstacle_front_outline() const { return {}; }
  virtual Shapes2d robot_front_outline(const State& /*s*/) const { return {}; }
};

}  // namespace amp::world
