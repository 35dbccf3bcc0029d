#include "problem_input.hpp"

#include <Eigen/Core>

#include "amp/core/error.hpp"

namespace amp::cli {

void add_map_query_options(CLI::App* cmd, MapQuery& q) {
  cmd->add_option("--start", q.start, "With a ROS map_server YAML as the problem: the start X Y")->expected(2);
  cmd->add_option("--goal", q.goal, "With a ROS map_server YAML as the problem: the goal X Y")->expected(2);
  cmd->add_option("--radius", q.radius, "With a ROS map_server YAML as the problem: the disc robot's radius [0.22]")
      ->check(CLI::PositiveNumber.description(""));
}

world::Problem load_problem_input(const std::string& file, const MapQuery& q, bool needs_goal, const CLI::App& cmd) {
  if (!world::is_map_server_yaml(file)) {
    for (const char* flag : {"--start", "--goal", "--radius"}) {
      if (cmd.count(flag) > 0) {
        throw Error(std::string(flag) + ": only with a ROS map_server YAML as the problem; " + file +
                    " is a problem file with its own");
      }
    }
    return world::load_problem(file);
  }
  if (q.start.empty()) {
    throw Error("--start: " + file + " is a ROS map_server map, not a problem file: give the start as --start X Y");
  }
  if (needs_goal && q.goal.empty()) {
    throw Error("--goal: " + file + " is a ROS map_server map, not a problem file: give the goal as --goal X Y");
  }
  const Eigen::Vector2d start(q.start[0], q.start[1]);
  const Eigen::Vector2d goal = q.goal.empty() ? start : Eigen::Vector2d(q.goal[0], q.goal[1]);
  return world::load_map_problem(file, start, goal, q.radius);
}

}  // namespace amp::cli
