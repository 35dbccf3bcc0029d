#pragma once
#include <memory>

#include "amp/nav/nav_world.hpp"
#include "amp/world/obstacle_source.hpp"
#include "amp/world/problem.hpp"

namespace amp::nav {

// The navigation world of a loaded 2-D world, sharing its data (ObstacleSource::obstacles_2d): a
// PolygonNavWorld for planar worlds (YAML and 2-D OMPL.app .cfg), a GridNavWorld for maps.
// Throws ParameterError for a 3-D world.
std::shared_ptr<const NavWorld> make_nav_world(const world::ObstacleSource& source);
// As above; the error names the problem file.
std::shared_ptr<const NavWorld> make_nav_world(const world::Problem& problem);

}  // namespace amp::nav
