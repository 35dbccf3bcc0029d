#include "amp/world/spatial_environment.hpp"

#include <array>

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

Outline SpatialEnvironment::obstacle_outline() const { return obstacles_seen_from(Eigen::Isometry3d::Identity()); }
Shapes2d SpatialEnvironment::robot_outline(const State& s) const { return robot_seen_from(Eigen::Isometry3d::Identity(), s); }
Outline SpatialEnvironment::obstacle_front_outline() const { return obstacles_seen_from(detail::front_view_frame()); }
Shapes2d SpatialEnvironment::robot_front_outline(const State& s) const {
  return robot_seen_from(detail::front_view_frame(), s);
}

}  // namespace amp::world
