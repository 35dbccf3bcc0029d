#pragma once
#include <memory>

namespace amp::world {

class OccupancyGrid;
class PlanarWorld;

// The obstacles of a 2-D world as data, shared with the environment, for modules that run their
// own geometry on them (nav: ray casting, a robot simulator). At most one is set.
struct Obstacles2d {
  std::shared_ptr<const PlanarWorld> planar;  // polygon / circle / segment worlds (YAML, 2-D .cfg)
  std::shared_ptr<const OccupancyGrid> grid;  // map worlds
};

// The role of a world that navigation uses: its 2-D obstacles as data. 3-D worlds have none.
class ObstacleSource {
 public:
  virtual ~ObstacleSource() = default;
  // The obstacles of a 2-D world; both null for 3-D worlds.
  virtual Obstacles2d obstacles_2d() const { return {}; }
};

}  // namespace amp::world
