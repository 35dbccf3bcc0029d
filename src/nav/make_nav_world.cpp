#include "amp/nav/make_nav_world.hpp"

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/polygon_nav_world.hpp"

namespace amp::nav {

std::shared_ptr<const NavWorld> make_nav_world(const world::ObstacleSource& source) {
  const world::Obstacles2d obstacles = source.obstacles_2d();
  if (obstacles.planar) return std::make_shared<const PolygonNavWorld>(obstacles.planar);
  if (obstacles.grid) return std::make_shared<const GridNavWorld>(obstacles.grid);
  throw ParameterError("navigation needs a 2-D world (polygons, circles or a map), not a 3-D one");
}

std::shared_ptr<const NavWorld> make_nav_world(const world::Problem& problem) {
  if (!problem.environment) throw ParameterError(problem.file.string() + ": the problem has no world");
  try {
    return make_nav_world(*problem.environment);
  } catch (const ParameterError& e) {
    throw ParameterError(problem.file.string() + ": " + e.what());
  }
}

}  // namespace amp::nav
