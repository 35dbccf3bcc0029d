#include "problem_input.hpp"

#include <Eigen/Core>

#include "amp/core/error.hpp"
#include "amp/world/arm_problem.hpp"

namespace amp::cli {

void add_map_query_options(CLI::App* cmd, MapQuery& q) {
  cmd->add_option("--start", q.start, "With a ROS map_server YAML as the problem: the start X Y")->expected(2);
  cmd->add_option("--goal", q.goal, "With a ROS map_server YAML as the problem: the goal X Y")->expected(2);
  cmd->add_option("--radius", q.radius, "With a ROS map_server YAML as the problem: the disc robot's radius [0.22]")
      ->check(CLI::PositiveNumber.description(""));
}

void add_problem_argument(CLI::App* cmd, std::string& problem) {
  cmd->add_option("problem", problem,
                  "Problem file (.yaml or OMPL.app .cfg), or a ROS map_server YAML with --start and --goal (or, "
                  "for an arm, none: --urdf, --srdf, --scene, --request)");
}

void add_arm_options(CLI::App* cmd, ArmInput& a) {
  cmd->add_option("--urdf", a.urdf, "An arm: its URDF (with --srdf, --scene and --request, instead of a problem file)");
  cmd->add_option("--srdf", a.srdf, "An arm: its SRDF (the planning group, disabled collision pairs)");
  cmd->add_option("--scene", a.scene, "An arm: a MoveIt PlanningScene YAML (the obstacles)");
  cmd->add_option("--request", a.request, "An arm: a MoveIt MotionPlanRequest YAML (group, start, joint goal)");
  cmd->add_option("--package-path", a.package_paths,
                  "An arm: a folder where package://NAME/... meshes are looked for, beside the URDF's (repeatable)");
  cmd->add_option("--collision", a.collision,
                  "An arm: check collisions on its meshes, or on spheres that cover them (generated, cached) [meshes]")
      ->check(CLI::IsMember({"meshes", "spheres"}));
  cmd->add_option("--spheres", a.spheres,
                  "An arm: a spherized URDF, grown to cover the meshes, as the sphere model (implies --collision spheres)");
}

namespace {

world::ProblemOverrides overrides_of(const ArmInput* a) {
  world::ProblemOverrides o;
  if (a != nullptr) {
    o.collision = a->collision.empty() && !a->spheres.empty() ? "spheres" : a->collision;
    o.spheres = a->spheres;
  }
  o.cache_dir = world::default_sphere_cache_dir();
  return o;
}

}  // namespace

world::Problem load_arm_input(const ArmInput& a, const std::string& problem_file) {
  if (!problem_file.empty()) {
    throw Error("--urdf: give either a problem file (" + problem_file + ") or --urdf, --srdf, --scene and --request");
  }
  const std::pair<const char*, const std::string*> flags[] = {
      {"--urdf", &a.urdf}, {"--srdf", &a.srdf}, {"--scene", &a.scene}, {"--request", &a.request}};
  for (const auto& [flag, value] : flags) {
    if (value->empty()) throw Error(std::string(flag) + ": an arm problem needs --urdf, --srdf, --scene and --request");
  }
  world::ArmFiles files{a.urdf, a.srdf, a.scene, a.request, {}, {}};
  for (const std::string& p : a.package_paths) files.package_paths.emplace_back(p);
  const world::ProblemOverrides o = overrides_of(&a);
  if (o.collision == "meshes" && !o.spheres.empty()) throw Error("--spheres: a spherized URDF needs --collision spheres");
  files.collision.model = o.collision.empty() ? world::ArmCollision::kMeshes : world::parse_arm_collision(o.collision, "--collision");
  files.collision.spheres = o.spheres;
  files.collision.cache_dir = o.cache_dir;
  return world::load_arm_problem(files);
}

world::Problem load_problem_input(const std::string& file, const MapQuery& q, bool needs_goal, const CLI::App& cmd,
                                  const ArmInput* arm) {
  if (!world::is_map_server_yaml(file)) {
    for (const char* flag : {"--start", "--goal", "--radius"}) {
      if (cmd.count(flag) > 0) {
        throw Error(std::string(flag) + ": only with a ROS map_server YAML as the problem; " + file +
                    " is a problem file with its own");
      }
    }
    return world::load_problem(file, overrides_of(arm));
  }
  if (arm != nullptr && (!arm->collision.empty() || !arm->spheres.empty())) {
    throw Error(std::string(arm->collision.empty() ? "--spheres" : "--collision") + ": " + file +
                " is a ROS map_server map; a collision model is chosen only for an arm");
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
