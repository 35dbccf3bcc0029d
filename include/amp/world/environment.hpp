#pragma once
#include "amp/world/checker_factory.hpp"
#include "amp/world/obstacle_source.hpp"
#include "amp/world/planning_features.hpp"
#include "amp/world/scene_model.hpp"
#include "amp/world/world_drawing.hpp"

namespace amp::world {

class GridEnvironment;

// A world with a robot in it, in its roles: it makes validity checkers (runs), draws itself (viz),
// gives its meshes to the 3-D viewer (scene model), tells planners its extent and the robot's size
// (features) and hands its 2-D obstacles to navigation. Code that needs one role takes that role's
// interface. Immutable once built, so one environment serves every thread. Implementations:
// PlanarEnvironment (2-D shapes), SpatialEnvironment (FCL), GridEnvironment (maps), ArmEnvironment.
class Environment : public CheckerFactory,
                    public WorldDrawing,
                    public SceneModelSource,
                    public PlanningFeatures,
                    public ObstacleSource {
 public:
  // This world as a map, or null when it is none: a method that plans on maps only (grid-dp) takes
  // it typed from here and says in one line what it needs otherwise.
  virtual const GridEnvironment* as_map() const { return nullptr; }
};

}  // namespace amp::world
