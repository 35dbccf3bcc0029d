#include "amp/world/planar_environment.hpp"

#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/solid_mesh.hpp"

namespace amp::world {

PlanarEnvironment::PlanarEnvironment(std::shared_ptr<const PlanarWorld> world, PlanarRobot robot,
                                     PlanarBoundsCheck bounds_check)
    : world_(std::move(world)), robot_(std::move(robot)), bounds_check_(bounds_check) {
  if (!world_) throw ParameterError("PlanarEnvironment: no world");
}

std::unique_ptr<ValidityChecker> PlanarEnvironment::make_checker(core::Counters& counters) const {
  return std::make_unique<PlanarChecker>(world_, robot_, counters, bounds_check_);
}

Eigen::AlignedBox3d PlanarEnvironment::workspace_bounds() const {
  const Eigen::AlignedBox2d& b = world_->bounds();
  return {Eigen::Vector3d(b.min().x(), b.min().y(), 0.0), Eigen::Vector3d(b.max().x(), b.max().y(), 0.0)};
}

Outline PlanarEnvironment::obstacle_outline() const { return Outline{world_->obstacles(), nullptr}; }

SceneModel PlanarEnvironment::scene_model() const {
  const FlatHeights h = flat_heights(world_->bounds());
  const Shapes2d& shapes = world_->obstacles();
  SceneModel model;
  model.flat = true;
  model.bounds = flat_bounds(world_->bounds(), h);
  // One mesh per polygon and circle; the segment walls (a projected surface) together.
  auto raise = [&](const Shapes2d& s) {
    model.obstacles.push_back(extrude_shapes(s, 0.0, h.obstacles, h.wall_thickness));
  };
  for (const Polygon& p : shapes.polygons) raise({{p}, {}});
  for (const Circle& c : shapes.circles) raise({{}, {c}});
  if (!shapes.segments.empty()) raise({{}, {}, shapes.segments});
  using Kind = PlanarRobot::Kind;
  const bool body = robot_.kind() == Kind::kRigid || robot_.kind() == Kind::kTranslating;
  for (std::size_t i = 0; i < robot_.links().size(); ++i) {
    model.robot_links.push_back(extrude_shapes(robot_.links()[i], 0.0, h.robot, h.wall_thickness));
    model.link_names.push_back(body ? std::string("body") : "link " + std::to_string(i));
  }
  return model;
}

void PlanarEnvironment::robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const {
  std::vector<Pose2> poses(static_cast<std::size_t>(robot_.link_count()));
  robot_.link_poses(s, poses.data());
  out.resize(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) out[i] = lift_pose(poses[i]);
}

Eigen::Vector3d PlanarEnvironment::reference_point(const State& s) const {
  const Eigen::Vector2d p = robot_.reference_point(s);
  return {p.x(), p.y(), 0.0};
}

}  // namespace amp::world
