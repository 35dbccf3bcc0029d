#include "amp/world/grid_yaml.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/map_server_loader.hpp"
#include "amp/world/movingai_loader.hpp"
#include "amp/world/planar_yaml.hpp"

namespace amp::world {

namespace {

constexpr double kDefaultResolutionFraction = 0.01;
// Edges are checked at most half a cell apart so that no step jumps a one-cell wall.
constexpr double kMaxStepInCells = 0.5;

std::shared_ptr<const OccupancyGrid> load_map(const YamlFields& world) {
  world.allow_only({"map", "resolution"});
  const std::filesystem::path file = world.file_path("map");
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".yaml" || ext == ".yml") {
    if (world.has("resolution")) world.fail("resolution", "only for MovingAI maps; map_server YAML sets its own");
    return std::make_shared<const OccupancyGrid>(load_map_server(file));
  }
  if (ext == ".map") {
    return std::make_shared<const OccupancyGrid>(load_movingai(file, world.positive("resolution", 1.0)));
  }
  world.fail("map", "expected a map_server .yaml or a MovingAI .map file, got '" + file.filename().string() + "'");
}

}  // namespace

LoadedWorld parse_grid_world(const YamlFields& root) {
  auto grid = load_map(root.child("world"));
  const YamlFields robot_fields = root.child("robot");
  robot_fields.allow_only({"type", "radius", "shapes"});
  const std::string type = robot_fields.string("type");
  GridRobot robot;
  if (type == "disc") {
    robot.kind = GridRobot::Kind::kDisc;
    robot.radius = robot_fields.positive("radius");
  } else if (type == "point") {
    robot_fields.allow_only({"type"});
    robot.kind = GridRobot::Kind::kPoint;
  } else if (type == "rigid2d") {
    robot.kind = GridRobot::Kind::kRigid;
    robot.body = parse_shapes2d(robot_fields.child("shapes"));  // the planar worlds' shape items
    if (robot.body.empty()) robot_fields.fail("shapes", "expected at least one shape");
  } else {
    robot_fields.fail("type", "expected disc, point or rigid2d, got '" + type + "'");
  }

  const double fraction = root.positive("resolution", kDefaultResolutionFraction);
  if (fraction > 1.0) root.fail("resolution", "expected a fraction in (0, 1], got " + std::to_string(fraction));
  const Eigen::AlignedBox2d e = grid->extent();
  auto env = std::make_shared<const GridEnvironment>(grid, std::move(robot));
  std::shared_ptr<core::JointSpace> space;
  if (env->robot().kind != GridRobot::Kind::kRigid) {
    space = std::make_shared<core::JointSpace>(
        core::make_rn_space({e.min().x(), e.min().y()}, {e.max().x(), e.max().y()}));
  } else {
    space = std::make_shared<core::JointSpace>(
        core::make_se2_space(e.min().x(), e.min().y(), e.max().x(), e.max().y(), env->robot_radius()));
  }
  space->set_resolution(std::min(fraction * space->maximum_extent(), kMaxStepInCells * grid->resolution()));
  return {std::move(space), std::move(env)};
}

}  // namespace amp::world
