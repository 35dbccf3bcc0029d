#pragma once
#include <memory>
#include <mutex>

#include "amp/world/environment.hpp"
#include "amp/world/spatial_checker.hpp"
#include "amp/world/spatial_robot.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world {

// A SpatialWorld with a SpatialRobot in it.
class SpatialEnvironment final : public Environment {
 public:
  SpatialEnvironment(std::shared_ptr<const SpatialWorld> world, SpatialRobot robot,
                     SpatialBoundsCheck bounds_check = SpatialBoundsCheck::kRobotAabb);

  int workspace_dimension() const override { return 3; }
  std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const override;
  Eigen::AlignedBox3d workspace_bounds() const override { return world_->bounds(); }
  // Top view: boxes and cylinders as projected convex hulls, spheres as circles, meshes as
  // their upward-facing triangles of non-zero projected area.
  Outline obstacle_outline() const override;
  // Top view of the robot: meshes as one convex hull each (cheap enough to draw along paths).
  Shapes2d robot_outline(const State& s) const override;
  // The same, seen from the front (WorldDrawing).
  bool has_front_view() const override { return true; }
  Outline obstacle_front_outline() const override;
  Shapes2d robot_front_outline(const State& s) const override;
  // The world's solids one mesh each; the robot's links by name ("body", "sphere", SCARA parts).
  SceneModel scene_model() const override;
  void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const override;
  Eigen::Vector3d reference_point(const State& s) const override { return robot_.reference_point(s); }
  double robot_min_diameter() const override { return robot_.min_diameter(); }
  double robot_radius() const override { return robot_.radius(); }

  const SpatialWorld& world() const { return *world_; }
  const SpatialRobot& robot() const { return robot_; }
  SpatialBoundsCheck bounds_check() const { return bounds_check_; }

 private:
  std::shared_ptr<const SpatialWorld> world_;
  SpatialRobot robot_;
  SpatialBoundsCheck bounds_check_;
  // The views: solids placed by `view` (identity: top; detail::front_view_frame(): front), projected.
  Outline obstacles_seen_from(const Eigen::Isometry3d& view) const;
  Shapes2d robot_seen_from(const Eigen::Isometry3d& view, const State& s) const;
  // FCL's CollisionObject constructor writes into the shared geometry (its local AABB), so
  // checkers are made one at a time.
  mutable std::mutex make_mutex_;
};

}  // namespace amp::world
