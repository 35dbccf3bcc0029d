#pragma once
#include <memory>

#include "amp/world/environment.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/planar_robot.hpp"
#include "amp/world/planar_world.hpp"

namespace amp::world {

// A planar robot in a PlanarWorld. Checkers are PlanarCheckers sharing the (immutable) world.
class PlanarEnvironment final : public Environment {
 public:
  // Throws ParameterError for a null world.
  PlanarEnvironment(std::shared_ptr<const PlanarWorld> world, PlanarRobot robot,
                    PlanarBoundsCheck bounds_check = PlanarBoundsCheck::kWholeRobot);
  PlanarBoundsCheck bounds_check() const { return bounds_check_; }

  const PlanarWorld& world() const { return *world_; }
  const PlanarRobot& robot() const { return robot_; }

  int workspace_dimension() const override { return 2; }
  std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const override;
  Eigen::AlignedBox3d workspace_bounds() const override;
  Outline obstacle_outline() const override;
  Shapes2d robot_outline(const State& s) const override { return robot_.outline(s); }
  // Link-0 origin for rigid and translating robots, the end of the last link for arms; z = 0.
  Eigen::Vector3d reference_point(const State& s) const override;
  double robot_min_diameter() const override { return robot_.min_diameter(); }
  double robot_radius() const override { return robot_.radius(); }
  Obstacles2d obstacles_2d() const override { return {world_, nullptr}; }

 private:
  std::shared_ptr<const PlanarWorld> world_;
  PlanarRobot robot_;
  PlanarBoundsCheck bounds_check_;
};

}  // namespace amp::world
