#include "amp/world/planar_environment.hpp"

#include "amp/core/error.hpp"
#include "amp/world/planar_checker.hpp"

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

Eigen::Vector3d PlanarEnvironment::reference_point(const State& s) const {
  const Eigen::Vector2d p = robot_.reference_point(s);
  return {p.x(), p.y(), 0.0};
}

}  // namespace amp::world
