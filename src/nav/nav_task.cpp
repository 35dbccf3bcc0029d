#include "amp/nav/nav_task.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/event_yaml.hpp"
#include "amp/nav/make_nav_world.hpp"

namespace amp::nav {

NavTask make_nav_task(const world::Problem& problem) {
  const std::string where = problem.file.empty() ? "problem '" + problem.name + "'" : problem.file.string();
  auto fail = [&](const std::string& what) { throw ParameterError(where + ": " + what); };
  std::shared_ptr<const NavWorld> world = make_nav_world(problem);  // names the file for a 3-D world
  if (!problem.space || problem.seeds.size() < 2) fail("the problem has no start and goal");
  // A disc is the one robot whose configuration is its centre alone, and whose reach from that
  // centre is half its smallest width; a rigid body or a point fails one of the two.
  const world::PlanningFeatures& features = *problem.environment;
  const double radius = features.robot_radius();
  const bool disc = problem.space->dimension() == 2 && radius > 0.0 &&
                    std::abs(features.robot_min_diameter() - 2.0 * radius) <= 1e-9 * std::max(1.0, radius);
  if (!disc) {
    fail("navigation methods drive a disc robot (robot: {type: disc, radius: r}); this robot is not a disc");
  }
  NavTask task;
  task.name = problem.name;
  task.robot_radius = radius;
  task.start = Eigen::Vector2d(problem.start()[0], problem.start()[1]);
  task.goal = Eigen::Vector2d(problem.goal()[0], problem.goal()[1]);
  try {
    task.timeline = std::make_shared<const WorldTimeline>(world, load_events(problem));
  } catch (const FileError&) {
    throw;  // names the file and the field already
  } catch (const ParameterError& e) {
    fail(e.what());
  }
  if (!world->disc_free(task.start, radius)) fail("start: the robot's disc is not free there");
  if (!world->disc_free(task.goal, radius)) fail("goal: the robot's disc is not free there");
  return task;
}

}  // namespace amp::nav
