#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amp/core/edge_check_mode.hpp"
#include "amp/core/space.hpp"
#include "amp/world/environment.hpp"

namespace amp::world {

// A node limit that never stops a run (OMPL.app's .cfg problems stop on time only).
inline constexpr std::size_t kNoNodeLimit = static_cast<std::size_t>(-1);

// Planner defaults a problem file may carry (`defaults:`); command-line options override them.
struct ProblemDefaults {
  std::string planner = "prm";
  double time_limit_s = 30.0;
  // Not given: the planner's own default (roadmap::resolve_node_limit), as grid-dp needs none.
  std::optional<std::size_t> node_limit;
  // Planner parameters this problem needs (e.g. the A* grid's `steps: 512` for the 6-DOF puzzle),
  // as written; they apply to every planner that declares them, unless the run sets them itself.
  std::map<std::string, std::string> params;
  // How planners check roadmap edges (`edge_check:`); solved paths are certified either way.
  core::EdgeCheckMode edge_check = core::EdgeCheckMode::kDiscrete;
};

// A loaded planning problem: space, world + robot, and the configurations to connect.
struct Problem {
  std::string name;
  std::filesystem::path file;  // where it was loaded from (empty if built in code)
  std::shared_ptr<const core::Space> space;
  std::shared_ptr<const Environment> environment;
  // Configurations to join: {start, goal} for a query, or the seeds Isto 2003 joins in order.
  std::vector<State> seeds;
  ProblemDefaults defaults;
  // Set when the problem's own files accept every seed but the model planned with does not (an
  // arm's sphere cover is larger than its meshes, docs/arms.md "Sphere model"): says which seed
  // and what it touches. Every run then reports kUnsolvable with it, without planning.
  std::string unsolvable_because;
  // Figures about the model that every run's record carries in its `extra` (an arm's sphere model:
  // `spheres`, and `sphere_kernels_avx2` 1 or 0 for the SIMD build the CPU runs).
  std::map<std::string, double> record_extra;

  const State& start() const { return seeds.front(); }
  const State& goal() const { return seeds.back(); }
};

// A world with its robot and the robot's configuration space, as a world parser builds them.
struct LoadedWorld {
  std::shared_ptr<const core::Space> space;
  std::shared_ptr<const Environment> environment;
};

// Loads a problem file: YAML (docs/problem-format.md) or OMPL.app `.cfg`, chosen by extension.
// Throws FileError naming the file and field on any fault, including start/goal out of bounds or
// in collision.
Problem load_problem(const std::filesystem::path& file);

// What a caller may set over a problem file (`amp plan --collision`, `--spheres`): an arm problem's
// collision model ("meshes" or "spheres"; empty: the file's `collision:`, else meshes), its
// spherized URDF (empty: the file's `spheres:`), and where generated spheres are cached (empty:
// default_sphere_cache_dir()). Throws FileError when `collision` or `spheres` is set and the file is
// not an arm problem.
struct ProblemOverrides {
  std::string collision;
  std::filesystem::path spheres;
  std::filesystem::path cache_dir;
};
Problem load_problem(const std::filesystem::path& file, const ProblemOverrides& overrides);

// Whether `file` is a ROS map_server YAML (a mapping with `image` and `resolution`, and neither
// `world` nor `robot`) rather than a problem file.
bool is_map_server_yaml(const std::filesystem::path& file);
// The problem a map_server map makes for a disc robot of `radius` going from start to goal (what a
// problem file with `world: {map: ...}` would give). Throws FileError as load_problem does, naming
// the map file, for a bad map, radius, or a start or goal that is outside or not free.
Problem load_map_problem(const std::filesystem::path& map_yaml, const Eigen::Vector2d& start,
                         const Eigen::Vector2d& goal, double radius);

}  // namespace amp::world
