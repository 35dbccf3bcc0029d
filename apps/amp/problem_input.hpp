#pragma once
// What `amp plan`, `amp explore` and `amp navigate` take as PROBLEM: a problem file, or a ROS
// map_server YAML with the query on the command line (a user with only a ROS map writes no file).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "amp/world/problem.hpp"

namespace amp::cli {

struct MapQuery {
  std::vector<double> start, goal;  // X Y each, or empty
  double radius = 0.22;             // m: Nav2's TurtleBot3 robot_radius
};

// --start X Y, --goal X Y and --radius R on `cmd`.
void add_map_query_options(CLI::App* cmd, MapQuery& q);

// A MoveIt user's four files instead of a problem file (`amp plan --urdf ... --request ...`).
struct ArmInput {
  std::string urdf, srdf, scene, request;
  std::vector<std::string> package_paths;
  std::string collision;  // --collision: meshes | spheres (empty: the problem's)
  std::string spheres;    // --spheres: a spherized URDF to grow into a cover
  bool given() const { return !urdf.empty() || !srdf.empty() || !scene.empty() || !request.empty(); }
};

// The PROBLEM argument of a command that also takes an arm's four files or a map with a query
// (`amp plan`, `amp view`): one help text for both.
void add_problem_argument(CLI::App* cmd, std::string& problem);

// --urdf, --srdf, --scene, --request, --package-path, --collision and --spheres on `cmd`.
void add_arm_options(CLI::App* cmd, ArmInput& a);

// The arm problem of the four files; throws amp::Error naming the flag when one is missing or a
// problem file is given too.
world::Problem load_arm_input(const ArmInput& a, const std::string& problem_file);

// The problem in `file`; for a map_server YAML, world::load_map_problem with the query's start, goal
// (the start when !needs_goal and no --goal) and radius. Throws amp::Error naming the flag for a map
// without --start (or --goal, when needed), or for --start/--goal/--radius given with a problem
// file, which carries its own.
// `arm` (may be null): --collision and --spheres over the problem file's.
world::Problem load_problem_input(const std::string& file, const MapQuery& q, bool needs_goal, const CLI::App& cmd,
                                  const ArmInput* arm = nullptr);

}  // namespace amp::cli
