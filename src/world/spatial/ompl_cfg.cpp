#include "amp/world/ompl_cfg.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <system_error>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/world/mesh_loader.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/spatial_environment.hpp"
#include "amp/world/outline_merge.hpp"
#include "world/spatial/projection.hpp"

namespace amp::world {

namespace {

using Section = std::map<std::string, std::string>;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The INI file as section -> key -> value (later duplicates win, as OMPL.app's planner lists
// repeat keys outside [problem]).
class CfgFile {
 public:
  explicit CfgFile(std::filesystem::path file) : file_(std::move(file)) {
    std::ifstream in(file_);
    if (!in) throw FileError(file_.string() + ": cannot open file");
    std::string line, section;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::string t = trim(line);
      if (t.empty() || t[0] == '#' || t[0] == ';') continue;
      if (t.front() == '[') {
        if (t.back() != ']' || t.size() < 3) fail_line(number, "malformed section header '" + t + "'");
        section = trim(t.substr(1, t.size() - 2));
        continue;
      }
      const auto eq = t.find('=');
      if (eq == std::string::npos || eq == 0) fail_line(number, "expected 'key = value', got '" + t + "'");
      if (section.empty()) fail_line(number, "key outside any [section]");
      sections_[section][trim(t.substr(0, eq))] = trim(t.substr(eq + 1));
    }
    if (!sections_.count("problem")) throw FileError(file_.string() + ": missing section [problem]");
  }

  bool has(const std::string& section, const std::string& key) const {
    const auto s = sections_.find(section);
    return s != sections_.end() && s->second.count(key) > 0;
  }
  std::string text(const std::string& section, const std::string& key) const {
    if (!has(section, key)) fail(section, key, "missing key");
    return sections_.at(section).at(key);
  }
  double number(const std::string& section, const std::string& key) const {
    const std::string v = text(section, key);
    std::size_t used = 0;
    double d = 0.0;
    try {
      d = std::stod(v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || trim(v.substr(used)) != "" || !std::isfinite(d)) fail(section, key, "expected a number, got '" + v + "'");
    return d;
  }
  double number(const std::string& section, const std::string& key, double fallback) const {
    return has(section, key) ? number(section, key) : fallback;
  }
  std::filesystem::path mesh_path(const std::string& key) const {
    const std::filesystem::path rel = text("problem", key);
    const std::filesystem::path full = rel.is_absolute() ? rel : file_.parent_path() / rel;
    std::error_code ec;  // a name the OS refuses (too long, ...) is "no such file", not an exception
    if (!std::filesystem::is_regular_file(full, ec)) fail("problem", key, "no such file '" + full.string() + "'");
    return full;
  }
  TriangleMesh mesh(const std::string& key) const {
    const std::filesystem::path path = mesh_path(key);
    try {
      return load_mesh(path, UpAxis::kZ);  // as assimp reads it: OMPL.app converts nothing
    } catch (const Error& e) {
      fail("problem", key, e.what());
    }
  }
  [[noreturn]] void fail(const std::string& section, const std::string& key, const std::string& what) const {
    throw FileError(file_.string() + ": [" + section + "] " + key + ": " + what);
  }
  const std::filesystem::path& file() const { return file_; }

 private:
  [[noreturn]] void fail_line(int number, const std::string& what) const {
    throw FileError(file_.string() + ":" + std::to_string(number) + ": " + what);
  }
  std::filesystem::path file_;
  std::map<std::string, Section> sections_;
};

State se3_state(const CfgFile& cfg, const std::string& which) {
  const std::string p = which + ".";
  const Eigen::Vector3d pos(cfg.number("problem", p + "x"), cfg.number("problem", p + "y"), cfg.number("problem", p + "z"));
  const double theta = cfg.number("problem", p + "theta", 0.0);
  Eigen::Vector3d axis(cfg.number("problem", p + "axis.x", 1.0), cfg.number("problem", p + "axis.y", 0.0),
                       cfg.number("problem", p + "axis.z", 0.0));
  if (!(axis.norm() > 0.0)) {
    if (theta != 0.0) cfg.fail("problem", p + "axis", "rotation axis must not be zero");
    axis = Eigen::Vector3d::UnitX();
  }
  return core::Se3Space::make_state(pos, Eigen::Quaterniond(Eigen::AngleAxisd(theta, axis.normalized())));
}

Eigen::AlignedBox3d volume(const CfgFile& cfg, const TriangleMesh& world, int dims) {
  const char* axes[] = {"x", "y", "z"};
  int present = 0;
  for (int i = 0; i < dims; ++i) {
    present += cfg.has("problem", std::string("volume.min.") + axes[i]);
    present += cfg.has("problem", std::string("volume.max.") + axes[i]);
  }
  if (present == 0) return mesh_bounds(world);  // OMPL.app infers the bounds from the world
  Eigen::AlignedBox3d box = mesh_bounds(world);
  for (int i = 0; i < dims; ++i) {
    box.min()[i] = cfg.number("problem", std::string("volume.min.") + axes[i]);
    box.max()[i] = cfg.number("problem", std::string("volume.max.") + axes[i]);
    if (!(box.min()[i] < box.max()[i])) cfg.fail("problem", std::string("volume.max.") + axes[i], "must exceed volume.min");
  }
  return box;
}

// OMPL.app's robot frame is the mean of all the robot file's vertices; a 2-D problem's robot stays
// at its own height (the plane z = 0 holds the frame, not the body's middle).
void recentre(TriangleMesh& robot, bool planar) {
  Eigen::Vector3d mean = vertex_mean(robot);
  if (planar) mean.z() = 0.0;
  for (Eigen::Vector3d& v : robot.vertices) v -= mean;
}

double max_norm(const TriangleMesh& mesh, int dims) {
  double r = 0.0;
  for (const Eigen::Vector3d& v : mesh.vertices) r = std::max(r, dims == 2 ? v.head<2>().norm() : v.norm());
  return r;
}

void load_3d(const CfgFile& cfg, TriangleMesh robot_mesh, const TriangleMesh& world_mesh, Problem& problem) {
  const Eigen::AlignedBox3d box = volume(cfg, world_mesh, 3);
  const double radius = std::max(max_norm(robot_mesh, 3), 1e-9);
  std::vector<Solid> obstacles{Solid::mesh_of(world_mesh)};
  auto world = std::make_shared<const SpatialWorld>(std::move(obstacles), box);
  SpatialRobot robot = SpatialRobot::rigid({Solid::mesh_of(robot_mesh)});
  problem.environment = std::make_shared<SpatialEnvironment>(world, std::move(robot), SpatialBoundsCheck::kReferencePoint);
  problem.space = std::make_shared<core::Se3Space>(box.min(), box.max(), radius);
  problem.seeds = {se3_state(cfg, "start"), se3_state(cfg, "goal")};
}

State se2_state(const CfgFile& cfg, const std::string& which) {
  // Read before filling: a throw inside Eigen's comma initializer trips its debug assertion.
  const double x = cfg.number("problem", which + ".x"), y = cfg.number("problem", which + ".y");
  const double theta = cfg.number("problem", which + ".theta", 0.0);
  State s(3);
  s << x, y, theta;
  return s;
}

// OMPL.app moves the robot in the plane z = 0 (SE2 at height 0) and checks it in 3-D, surface
// against surface; the robot's body sweeps the slab of its own z range, so the world's surface
// within that slab, seen from above, is what it can touch, and the robot's shadow is what touches
// it (exact for the vertical prisms of OMPL.app's planar problems).
void load_2d(const CfgFile& cfg, const TriangleMesh& robot_mesh, const TriangleMesh& world_mesh, Problem& problem) {
  const Eigen::AlignedBox3d box = volume(cfg, world_mesh, 2);
  const Eigen::AlignedBox3d robot_box = mesh_bounds(robot_mesh);
  Shapes2d obstacles, body;
  detail::project_slab_surface(world_mesh, robot_box.min().z(), robot_box.max().z(), obstacles);
  detail::project_triangles(robot_mesh, Eigen::Isometry3d::Identity(), body);
  if (body.polygons.empty()) cfg.fail("problem", "robot", "mesh has no triangle of non-zero area in the plane");
  // The same closed sets in fewer pieces: a prism's cap triangles become its outline, and the
  // walls along a region's edges go (a check costs the edges it walks).
  body.polygons = merge_tiles(std::move(body.polygons));
  obstacles.polygons = merge_tiles(std::move(obstacles.polygons));
  drop_segments_on_polygon_edges(obstacles);
  const Eigen::AlignedBox2d bounds(box.min().head<2>(), box.max().head<2>());
  try {
    auto world = std::make_shared<const PlanarWorld>(std::move(obstacles), bounds);
    problem.environment = std::make_shared<PlanarEnvironment>(world, PlanarRobot::rigid(std::move(body)),
                                                              PlanarBoundsCheck::kReferencePoint);
  } catch (const ParameterError& e) {
    cfg.fail("problem", "world", e.what());
  }
  const double radius = std::max(max_norm(robot_mesh, 2), 1e-9);
  problem.space = std::make_shared<core::JointSpace>(
      core::make_se2_space(bounds.min().x(), bounds.min().y(), bounds.max().x(), bounds.max().y(), radius));
  problem.seeds = {se2_state(cfg, "start"), se2_state(cfg, "goal")};
}

}  // namespace

Problem load_ompl_cfg(const std::filesystem::path& file) {
  const CfgFile cfg(file);
  Problem problem;
  problem.file = file;
  problem.name = cfg.has("problem", "name") ? cfg.text("problem", "name") : file.stem().string();
  TriangleMesh robot_mesh = cfg.mesh("robot");
  const TriangleMesh world_mesh = cfg.mesh("world");
  for (const char* key : {"start.x", "start.y", "goal.x", "goal.y"}) cfg.text("problem", key);  // required
  // 3-D when the start has a height or a rotation axis, as OMPL.app's own problems are written.
  const bool spatial = cfg.has("problem", "start.z") || cfg.has("problem", "start.axis.x");
  recentre(robot_mesh, !spatial);
  if (spatial) {
    load_3d(cfg, std::move(robot_mesh), world_mesh, problem);
  } else {
    load_2d(cfg, robot_mesh, world_mesh, problem);
  }
  if (cfg.has("solver", "planner")) problem.defaults.planner = cfg.text("solver", "planner");
  const double limit = cfg.has("solver", "time_limit") ? cfg.number("solver", "time_limit")
                                                        : cfg.number("benchmark", "time_limit", problem.defaults.time_limit_s);
  if (!(limit > 0.0)) cfg.fail(cfg.has("solver", "time_limit") ? "solver" : "benchmark", "time_limit", "must be positive");
  problem.defaults.time_limit_s = limit;
  problem.defaults.node_limit = kNoNodeLimit;  // OMPL.app stops on its time limit only
  return problem;
}

}  // namespace amp::world
