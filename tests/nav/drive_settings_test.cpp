// nav/drive_settings.hpp: map_world, the one place policy-search and dwa take their map from
// (NavWorld::as_map), with a one-line error naming the method and the problem otherwise.
#include "amp/nav/drive_settings.hpp"

#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "support/bundled_problems.hpp"

namespace amp::nav {
namespace {

TEST(MapWorld, IsTheTasksBaseMap) {
  const world::Problem& p = test::bundled_problem("office-map.yaml");
  const NavTask task = make_nav_task(p);
  const GridNavWorld& map = map_world(task, "dwa");
  EXPECT_EQ(&map, task.timeline->base()->as_map());
  EXPECT_EQ(&map.grid(), p.environment->obstacles_2d().grid.get());  // the problem's own map
}

TEST(MapWorld, APolygonWorldGetsOneLineNamingTheMethodAndTheProblem) {
  const world::Problem& p = test::bundled_problem("office-polygons.yaml");
  const NavTask task = make_nav_task(p);
  try {
    map_world(task, "dwa");
    FAIL() << "a polygon world was taken as a map";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()),
              "dwa plans on map worlds (map_server or MovingAI); problem '" + p.name + "' is not one");
  }
}

// The same refusal reaches a caller of execute_navigation as ParameterError, not as a failed run.
TEST(MapWorld, MapMethodsRefusePolygonProblems) {
  const world::Problem& p = test::bundled_problem("office-polygons.yaml");
  for (const char* method : {"policy-search", "dwa"}) {
    try {
      execute_navigation(p, method, {}, 1, 10.0);
      FAIL() << method << " ran on a polygon world";
    } catch (const ParameterError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find(std::string(method) + " plans on map worlds"), 0u) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace amp::nav
