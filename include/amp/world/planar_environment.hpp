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
  // Obstacles and links extruded upward (flat_heights of the bounds); links "body" for a rigid or
  // translating robot, "link 0", "link 1", ... for arms and linkages.
  SceneModel scene_model() const override;
  void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const override;
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
