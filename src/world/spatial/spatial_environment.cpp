#include "amp/world/spatial_environment.hpp"

#include <array>
#include <string>
#include <vector>

#include "amp/world/solid_mesh.hpp"
#include "world/spatial/projection.hpp"

namespace amp::world {

SpatialEnvironment::SpatialEnvironment(std::shared_ptr<const SpatialWorld> world, SpatialRobot robot,
                                       SpatialBoundsCheck bounds_check)
    : world_(std::move(world)), robot_(std::move(robot)), bounds_check_(bounds_check) {}

std::unique_ptr<ValidityChecker> SpatialEnvironment::make_checker(core::Counters& counters) const {
  const std::lock_guard<std::mutex> lock(make_mutex_);
  return std::make_unique<SpatialChecker>(world_, robot_, bounds_check_, counters);
}

Outline SpatialEnvironment::obstacles_seen_from(const Eigen::Isometry3d& view) const {
  Outline outline;
  for (const Solid& s : world_->obstacles()) detail::project_solid(s, view, true, outline.shapes);
  return outline;
}

Shapes2d SpatialEnvironment::robot_seen_from(const Eigen::Isometry3d& view, const State& s) const {
  std::array<Eigen::Isometry3d, SpatialRobot::kMaxLinks> poses;
  robot_.link_poses(s, poses.data());
  Shapes2d out;
  for (int l = 0; l < robot_.link_count(); ++l) {
    for (const Solid& solid : robot_.link_solids(l)) {
      detail::project_solid(solid, view * poses[static_cast<std::size_t>(l)], false, out);
    }
  }
  return out;
}

namespace {

// The viewer's names of the links, in SpatialRobot's link order (its header lists them).
std::vector<std::string> link_names(const SpatialRobot& robot) {
  switch (robot.kind()) {
    case SpatialRobot::Kind::kRigid:
      return {"body"};
    case SpatialRobot::Kind::kSphere:
      return {"sphere"};
    case SpatialRobot::Kind::kScara:
      break;
  }
  return {"column", "upper arm", "forearm", "wrist", "tool"};
}

}  // namespace

SceneModel SpatialEnvironment::scene_model() const {
  SceneModel model;
  for (const Solid& s : world_->obstacles()) model.obstacles.push_back(solid_mesh(s));
  for (int l = 0; l < robot_.link_count(); ++l) {
    TriangleMesh link;
    for (const Solid& s : robot_.link_solids(l)) append_mesh(link, solid_mesh(s));
    model.robot_links.push_back(std::move(link));
  }
  model.link_names = link_names(robot_);
  model.bounds = world_->bounds();
  return model;
}

void SpatialEnvironment::robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const {
  out.resize(static_cast<std::size_t>(robot_.link_count()));
  robot_.link_poses(s, out.data());
}

Outline SpatialEnvironment::obstacle_outline() const { return obstacles_seen_from(Eigen::Isometry3d::Identity()); }
Shapes2d SpatialEnvironment::robot_outline(const State& s) const { return robot_seen_from(Eigen::Isometry3d::Identity(), s); }
Outline SpatialEnvironment::obstacle_front_outline() const { return obstacles_seen_from(detail::front_view_frame()); }
Shapes2d SpatialEnvironment::robot_front_outline(const State& s) const {
  return robot_seen_from(detail::front_view_frame(), s);
}

}  // namespace amp::world
