#pragma once
#include "amp/world/checker_factory.hpp"
#include "amp/world/obstacle_source.hpp"
#include "amp/world/planning_features.hpp"
#include "amp/world/world_drawing.hpp"

namespace amp::world {

// A world with a robot in it, in its roles: it makes validity checkers (runs), draws itself (viz),
// tells planners its extent and the robot's size (features) and hands its 2-D obstacles to
// navigation. Code that needs one role takes that role's interface. Immutable once built, so one
// environment serves every thread. Implementations: PlanarEnvironment (2-D shapes),
// SpatialEnvironment (FCL), GridEnvironment (maps).
class Environment : public CheckerFactory, public WorldDrawing, public PlanningFeatures, public ObstacleSource {};

}  // namespace amp::world
