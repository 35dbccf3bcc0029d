#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amp/core/run_record.hpp"
#include "amp/nav/nav_task.hpp"

namespace amp::core {
class Rng;
class StopCondition;
}  // namespace amp::core

namespace amp::nav {

// A stage of a method's plan before it drives, for pictures: policy search's value-function path,
// then its waypoints after each step of Table 1 (the policy-search paper's Figure 3).
struct PlanStage {
  std::string name;
  std::vector<Eigen::Vector2d> points;
  bool waypoints = true;         // the points are waypoints (not a cell path)
  std::optional<double> value;   // the plan's value at this stage, where the method has one
};

// How a drive to one goal went, typed (the record's extras hold the same numbers by name, for
// `amp bench`): the studies read it here, not back from the record by key.
struct DriveSummary {
  bool arrived = false;
  double execution_time_s = 0.0;  // simulated
  double distance = 0.0;
  double min_clearance = 0.0;
  std::size_t collisions = 0;  // footprint contacts
  std::optional<std::size_t> waypoints;  // the plan's, for methods that plan waypoints
};

// What one navigation run reports: the flat record `amp bench` writes (status, path_length,
// wall_time_s, and the method's metrics in `extra`), and the robot's driven trace.
struct NavigationOutcome {
  core::RunRecord record;
  std::vector<Eigen::Vector2d> trace;
  std::vector<double> speeds;    // per step, when the method drives a controller (the velocity profile)
  double planning_time_s = 0.0;  // measured, so outside the record (which depends on the seed alone)
  std::vector<PlanStage> stages;  // empty for methods that do not plan ahead
  std::optional<DriveSummary> drive;  // for methods that drive to one goal (policy-search, dwa)
};

// A navigation method (PGCS exploration and queries, policy search, DWA, SINS): it drives a
// simulated robot in the task's world. Every random draw comes from `rng`; the run ends when
// `stop` fires (status kTimeout) or the method is done. Implementations: PgcsNavigator,
// PolicyNavigator, DwaNavigator, SinsNavigator.
class Navigator {
 public:
  virtual ~Navigator() = default;
  virtual NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) = 0;
};

}  // namespace amp::nav
