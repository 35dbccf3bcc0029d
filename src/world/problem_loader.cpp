#include <algorithm>
#include <sstream>
#include <utility>

#include "amp/core/edge_steps.hpp"
#include "amp/core/error.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/grid_yaml.hpp"
#include "amp/world/ompl_cfg.hpp"
#include "amp/world/planar_yaml.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/spatial_yaml.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::world {

namespace {

std::string format_state(const State& s) {
  std::ostringstream out;
  out << '[';
  for (int i = 0; i < s.size(); ++i) out << (i ? ", " : "") << s[i];
  out << ']';
  return out.str();
}

bool is_spatial_robot(const std::string& type) { return type == "rigid3d" || type == "sphere" || type == "scara"; }

State read_state(const YamlFields& f, const core::Space& space) {
  const std::vector<double> v = f.as_numbers();
  if (static_cast<int>(v.size()) != space.dimension()) {
    f.fail("", "expected " + std::to_string(space.dimension()) + " coordinates for a " + std::string(space.kind()) +
                   " state, got " + std::to_string(v.size()));
  }
  State s(space.dimension());
  for (int i = 0; i < space.dimension(); ++i) s[i] = v[i];
  if (space.kind() == "se3") {
    const double n = s.tail<4>().norm();
    if (n < 1e-9) f.fail("", "quaternion (qx, qy, qz, qw) has zero length");
    s.tail<4>() /= n;  // users write rotations to a few digits; any non-zero quaternion names one
  }
  return s;
}

// `edge_check:` and `defaults:` (planner, limits, parameters), which every kind of problem file may carry.
void read_run_defaults(const YamlFields& root, Problem& p) {
  if (root.has("edge_check")) {
    try {
      p.defaults.edge_check = core::parse_edge_check_mode(root.string("edge_check"));
    } catch (const ParameterError& e) {
      root.fail("edge_check", e.what());
    }
  }
  if (root.has("defaults")) {
    const YamlFields d = root.child("defaults");
    d.allow_only({"planner", "time_limit", "node_limit", "params"});
    p.defaults.planner = d.string("planner", p.defaults.planner);
    p.defaults.time_limit_s = d.positive("time_limit", p.defaults.time_limit_s);
    if (d.has("node_limit")) {  // absent: the planner's own default
      const long long nl = d.integer("node_limit", 0);
      if (nl <= 0) d.fail("node_limit", "expected a positive integer, got " + std::to_string(nl));
      p.defaults.node_limit = static_cast<std::size_t>(nl);
    }
    if (d.has("params")) {
      const YamlFields params = d.child("params");
      for (const std::string& key : params.keys()) p.defaults.params[key] = params.string(key);
    }
  }
}

// A problem file naming a MoveIt user's four files (docs/problem-format.md, "Arms"), paths relative
// to the problem file.
// The collision model: the caller's over the file's (`collision:`, `spheres:`); a spherized URDF
// alone implies spheres.
ArmCollisionOptions arm_collision(const YamlFields& root, const ProblemOverrides& overrides) {
  ArmCollisionOptions c;
  c.spheres = !overrides.spheres.empty() ? overrides.spheres : root.has("spheres") ? root.file_path("spheres") : "";
  std::string model = overrides.collision;
  if (model.empty() && root.has("collision")) model = root.string("collision", "meshes");
  if (model.empty()) model = c.spheres.empty() ? "meshes" : "spheres";
  try {
    c.model = parse_arm_collision(model, "collision");
  } catch (const ParameterError& e) {
    root.fail("collision", e.what());
  }
  if (c.model == ArmCollision::kMeshes && !c.spheres.empty()) {
    root.fail("spheres", "a spherized URDF is used only with collision: spheres");
  }
  c.cache_dir = overrides.cache_dir.empty() ? default_sphere_cache_dir() : overrides.cache_dir;
  return c;
}

Problem yaml_arm_problem(const YamlFields& root, const std::filesystem::path& file, const ProblemOverrides& overrides) {
  root.allow_only({"name", "description", "urdf", "srdf", "scene", "request", "package_paths", "defaults", "edge_check",
                   "collision", "spheres"});
  ArmFiles files{root.file_path("urdf"), root.file_path("srdf"), root.file_path("scene"), root.file_path("request"), {},
                 arm_collision(root, overrides)};
  if (root.has("package_paths")) {
    const YamlFields paths = root.child("package_paths");
    for (std::size_t i = 0; i < paths.size(); ++i) {
      const YAML::Node n = paths.element(i).node();
      if (!n.IsScalar()) paths.element(i).fail("", "expected a folder");
      files.package_paths.push_back(file.parent_path() / n.Scalar());
    }
  }
  Problem p = load_arm_problem(files);
  p.name = root.string("name", p.name);
  p.file = file;
  return p;
}

Problem yaml_problem(const YamlFields& root, const std::filesystem::path& file, const ProblemOverrides& overrides = {}) {
  if (!root.is_map()) root.fail("", "a problem file must be a YAML mapping");
  if (root.has("urdf")) {
    Problem p = yaml_arm_problem(root, file, overrides);
    read_run_defaults(root, p);
    return p;
  }
  if (!overrides.collision.empty() || !overrides.spheres.empty()) {
    root.fail("", "a collision model (meshes or spheres) is chosen only for an arm problem (urdf:)");
  }
  // `events:` (obstacles that appear or vanish while a robot drives) belongs to the nav module's
  // simulator, which reads it itself (nav::load_events); planners ignore it.
  root.allow_only({"name", "description", "bounds", "resolution", "world", "robot", "start", "goal", "seeds",
                   "defaults", "edge_check", "events"});
  // Held here, for every world type: below the floor one edge would take longer than any run, and
  // the usual cause is an absolute step written where a fraction of the extent is expected.
  static_assert(core::kMinResolutionFraction == 1e-9, "the message names the floor");
  if (root.has("resolution") && root.positive("resolution") < core::kMinResolutionFraction) {
    root.fail("resolution", "expected a fraction of the space's extent of at least 1e-9 (an edge across the "
                            "space then takes 10^9 CD calls), got '" + root.node()["resolution"].Scalar() + "'");
  }
  const std::string robot_type = root.child("robot").string("type");

  LoadedWorld loaded;
  // `world:` is optional (no world is an empty one), so only look inside it when it is there.
  if (root.has("world") && root.child("world").has("map")) {
    loaded = parse_grid_world(root);
  } else if (is_spatial_robot(robot_type)) {
    loaded = parse_spatial_world(root);
  } else {
    loaded = parse_planar_world(root);
  }

  Problem p;
  p.name = root.string("name", file.stem().string());
  p.file = file;
  p.space = loaded.space;
  p.environment = loaded.environment;
  if (root.has("seeds")) {
    if (root.has("start") || root.has("goal")) root.fail("seeds", "give either seeds or start/goal, not both");
    const YamlFields seeds = root.child("seeds");
    if (seeds.size() < 2) seeds.fail("", "at least two seed configurations are needed");
    for (std::size_t i = 0; i < seeds.size(); ++i) p.seeds.push_back(read_state(seeds.element(i), *p.space));
  } else {
    p.seeds.push_back(read_state(root.child("start"), *p.space));
    p.seeds.push_back(read_state(root.child("goal"), *p.space));
  }
  read_run_defaults(root, p);
  return p;
}

Problem load_yaml_problem(const std::filesystem::path& file, const ProblemOverrides& overrides) {
  return yaml_problem(YamlFields(load_yaml_file(file), file, ""), file, overrides);
}

std::string seed_name(const Problem& p, std::size_t i) {
  if (p.seeds.size() == 2) return i == 0 ? "start" : "goal";
  return "seeds[" + std::to_string(i) + "]";
}

// Every seed must lie in bounds and be free: a planner cannot fix a bad query, so say so up front.
void validate_seeds(const Problem& p) {
  if (!p.unsolvable_because.empty()) return;  // checked against the exact geometry by its loader
  core::Counters scratch;
  const auto checker = p.environment->make_checker(scratch);
  for (std::size_t i = 0; i < p.seeds.size(); ++i) {
    const State& s = p.seeds[i];
    if (!p.space->in_bounds(s)) {
      throw FileError(p.file.string() + ": " + seed_name(p, i) + ": configuration " + format_state(s) +
                      " is outside the space's bounds");
    }
    if (!checker->is_valid(s)) {
      throw FileError(p.file.string() + ": " + seed_name(p, i) + ": configuration " + format_state(s) +
                      " is in collision (or outside the workspace)");
    }
  }
}

}  // namespace

Problem load_problem(const std::filesystem::path& file) { return load_problem(file, ProblemOverrides{}); }

Problem load_problem(const std::filesystem::path& file, const ProblemOverrides& overrides) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw FileError(file.string() + ": no such file");
  if (!std::filesystem::is_regular_file(file, ec)) throw FileError(file.string() + ": not a regular file");
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  Problem p;
  if (ext == ".cfg") {
    if (!overrides.collision.empty() || !overrides.spheres.empty()) {
      throw FileError(file.string() + ": a collision model (meshes or spheres) is chosen only for an arm problem");
    }
    p = load_ompl_cfg(file);
  } else if (ext == ".yaml" || ext == ".yml") {
    p = load_yaml_problem(file, overrides);
  } else {
    throw FileError(file.string() + ": unknown problem format '" + ext + "' (expected .yaml, .yml or .cfg)");
  }
  validate_seeds(p);
  return p;
}

bool is_map_server_yaml(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".yaml" && ext != ".yml") return false;
  try {
    const YAML::Node root = load_yaml_file(file);
    return root.IsMap() && root["image"] && root["resolution"] && !root["world"] && !root["robot"];
  } catch (const std::exception&) {
    return false;  // not readable as YAML: load_problem will say why
  }
}

Problem load_map_problem(const std::filesystem::path& map_yaml, const Eigen::Vector2d& start,
                         const Eigen::Vector2d& goal, double radius) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(map_yaml, ec)) throw FileError(map_yaml.string() + ": no such file");
  // The problem file a user would write for the map, built in memory.
  YAML::Node root;
  root["name"] = map_yaml.stem().string();
  root["world"]["map"] = std::filesystem::absolute(map_yaml).string();
  root["robot"]["type"] = "disc";
  root["robot"]["radius"] = radius;
  for (const auto& [key, v] : {std::pair{"start", start}, std::pair{"goal", goal}}) {
    root[key].push_back(v.x());
    root[key].push_back(v.y());
  }
  Problem p = yaml_problem(YamlFields(root, map_yaml, ""), map_yaml);
  validate_seeds(p);
  return p;
}

}  // namespace amp::world
